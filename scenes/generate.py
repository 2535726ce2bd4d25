#!/usr/bin/env python3
"""Writes the test scenes of smallmlt into this folder: NAME.scene, NAME.mtl,
the meshes NAME/MATERIAL.obj (one per material) and NAME.xml, the same scene
for Mitsuba 3 (blender-export's .xml reads its objects from
blender-export/OBJECT.obj: Mitsuba's obj shape has one BSDF).

Every scene is built from quads and meshes generated here; nothing is
downloaded. Run `python3 scenes/generate.py` after changing it and commit the
output. Front faces (counter-clockwise winding) face where the comments say;
only emitters care, diffuse and mirror surfaces are two-sided.
"""
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def normalize(a):
    return scale(a, 1.0 / math.sqrt(dot(a, a)))


class Mesh:
    """Triangles grouped by material, written as one OBJ."""

    def __init__(self):
        self.verts = []
        self.normals = []
        self.faces = []  # (material, (i, j, k), (ni, nj, nk) or None), 1-based

    def vertex(self, p):
        self.verts.append(p)
        return len(self.verts)

    def normal(self, n):
        self.normals.append(normalize(n))
        return len(self.normals)

    def tri(self, mat, a, b, c, facing=None, normals=None):
        """Triangle a b c; with `facing`, wound so its normal points that way;
        `normals`: shading normals at a, b, c (written as vn)."""
        if facing is not None and dot(cross(sub(b, a), sub(c, a)), facing) < 0:
            b, c = c, b
            if normals is not None:
                normals = (normals[0], normals[2], normals[1])
        ns = None if normals is None else tuple(self.normal(n) for n in normals)
        self.faces.append((mat, (self.vertex(a), self.vertex(b), self.vertex(c)), ns))

    def quad(self, mat, center, u, v, facing):
        """Parallelogram center +- u +- v, front face toward `facing`."""
        p = [add(add(center, scale(u, su)), scale(v, sv))
             for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        self.tri(mat, p[0], p[1], p[2], facing)
        self.tri(mat, p[0], p[2], p[3], facing)

    def box(self, mat, lo, hi, inward=False, skip=()):
        """Axis-aligned box; faces point outward (or inward). skip: face names."""
        c = scale(add(lo, hi), 0.5)
        h = scale(sub(hi, lo), 0.5)
        s = -1 if inward else 1
        faces = {
            "-x": ((c[0] - h[0], c[1], c[2]), (0, h[1], 0), (0, 0, h[2]), (-s, 0, 0)),
            "+x": ((c[0] + h[0], c[1], c[2]), (0, h[1], 0), (0, 0, h[2]), (s, 0, 0)),
            "-y": ((c[0], c[1] - h[1], c[2]), (h[0], 0, 0), (0, 0, h[2]), (0, -s, 0)),
            "+y": ((c[0], c[1] + h[1], c[2]), (h[0], 0, 0), (0, 0, h[2]), (0, s, 0)),
            "-z": ((c[0], c[1], c[2] - h[2]), (h[0], 0, 0), (0, h[1], 0), (0, 0, -s)),
            "+z": ((c[0], c[1], c[2] + h[2]), (h[0], 0, 0), (0, h[1], 0), (0, 0, s)),
        }
        for name, (center, u, v, n) in faces.items():
            if name not in skip:
                self.quad(mat, center, u, v, n)

    def rotated_block(self, mat, base_center, half, height, angle_deg):
        """A box standing on y = base_center.y, turned about the vertical axis."""
        a = math.radians(angle_deg)
        ux = (math.cos(a) * half[0], 0, math.sin(a) * half[0])
        uz = (-math.sin(a) * half[1], 0, math.cos(a) * half[1])
        hy = (0, height / 2, 0)
        c = add(base_center, hy)
        self.quad(mat, add(c, hy), ux, uz, (0, 1, 0))
        self.quad(mat, sub(c, hy), ux, uz, (0, -1, 0))
        for d, other in ((ux, uz), (scale(ux, -1), uz), (uz, ux), (scale(uz, -1), ux)):
            self.quad(mat, add(c, d), other, hy, d)

    def sphere(self, mat, center, radius, subdivisions=3, inward=False):
        """Icosphere with outward (or inward) faces."""
        t = (1 + math.sqrt(5)) / 2
        pts = [normalize(p) for p in [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0),
                                      (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
                                      (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
        tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9),
                (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2),
                (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
                (8, 6, 7), (9, 8, 1)]
        tris = [tuple(pts[i] for i in f) for f in tris]
        for _ in range(subdivisions):
            nxt = []
            for a, b, c in tris:
                ab = normalize(scale(add(a, b), 0.5))
                bc = normalize(scale(add(b, c), 0.5))
                ca = normalize(scale(add(c, a), 0.5))
                nxt += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
            tris = nxt
        for a, b, c in tris:
            n = scale(add(add(a, b), c), -1 if inward else 1)
            self.tri(mat, *(add(center, scale(p, radius)) for p in (a, b, c)), facing=n)

    def groups(self):
        """The faces by material, those with shading normals apart (Mitsuba
        reads a mesh's normals for all its faces or none), in the order they
        first appear: (material, file name, faces)."""
        order, by = [], {}
        for face in self.faces:
            key = (face[0], face[2] is not None)
            if key not in by:
                order.append(key)
                by[key] = []
            by[key].append(face)
        both = {m for m, smooth in order if smooth} & {m for m, smooth in order if not smooth}
        return [(m, m + ("-flat" if m in both and not smooth else ""), by[(m, smooth)])
                for m, smooth in order]

    def write(self, folder, mtl_path):
        """One OBJ per material, FOLDER/MATERIAL.obj, each with the vertices
        it uses; returns their paths relative to this folder, in order."""
        os.makedirs(os.path.join(HERE, folder), exist_ok=True)
        paths = []
        for mat, file_name, faces in self.groups():
            rel = "%s/%s.obj" % (folder, file_name)
            vmap, nmap = {}, {}
            for _, vs, ns in faces:
                for i in vs:
                    vmap.setdefault(i, len(vmap) + 1)
                for i in ns or ():
                    nmap.setdefault(i, len(nmap) + 1)
            with open(os.path.join(HERE, rel), "w") as f:
                f.write("# generated by scenes/generate.py\nmtllib %s\n" % mtl_path)
                for i in vmap:
                    f.write("v %.6f %.6f %.6f\n" % self.verts[i - 1])
                for i in nmap:
                    f.write("vn %.6f %.6f %.6f\n" % self.normals[i - 1])
                f.write("usemtl %s\n" % mat)
                for _, vs, ns in faces:
                    if ns is None:
                        f.write("f %d %d %d\n" % tuple(vmap[i] for i in vs))
                    else:
                        f.write("f %d//%d %d//%d %d//%d\n" % tuple(
                            x for i, n in zip(vs, ns) for x in (vmap[i], nmap[n])))
            paths.append((mat, rel, any(ns is not None for _, _, ns in faces)))
        return paths


CORNELL_MATERIALS = """\
newmtl white
Kd 0.75 0.75 0.75
newmtl red
Kd 0.63 0.065 0.05
newmtl green
Kd 0.14 0.45 0.091
"""


def cornell_walls(m):
    """The box x, z in [-1, 1], y in [0, 2], open toward the camera (+z)."""
    m.quad("white", (0, 0, 0), (0, 0, 1), (1, 0, 0), (0, 1, 0))     # floor
    m.quad("white", (0, 2, 0), (0, 0, 1), (1, 0, 0), (0, -1, 0))    # ceiling
    m.quad("white", (0, 1, -1), (1, 0, 0), (0, 1, 0), (0, 0, 1))    # back
    m.quad("red", (-1, 1, 0), (0, 0, 1), (0, 1, 0), (1, 0, 0))      # left
    m.quad("green", (1, 1, 0), (0, 0, 1), (0, 1, 0), (-1, 0, 0))    # right


def parse_mtl(text):
    """The materials of MTL text: name -> {directive: its value text}."""
    mats, cur = {}, None
    for line in text.splitlines():
        t = line.split("#")[0].split()
        if not t:
            continue
        if t[0] == "newmtl":
            cur = mats.setdefault(t[1], {})
        else:
            cur[t[0]] = " ".join(t[1:])
    return mats


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def mitsuba_bsdf(m):
    """The Mitsuba BSDF that smallmlt reads as the material its MTL reader
    makes of `m` (the rows of doc/scene-format.md the generated scenes use),
    and the area emitter's radiance or None."""
    illum = int(m.get("illum", "1"))
    kd = m.get("Kd", "0 0 0")
    if "map_Kd" in m:
        kd_xml = ('<texture type="bitmap" name="%%s"><string name="filename" value="%s"/></texture>'
                  % m["map_Kd"])
    else:
        kd_xml = '<rgb name="%%s" value="%s"/>' % kd
    metal = float(m.get("Pm", "0")) >= 0.5
    r = f32(float(m.get("Pr", "0")))
    alpha = "%.9g" % f32(r * r)
    rough = f32(r * r) >= 1e-3
    ggx = '<string name="distribution" value="ggx"/><float name="alpha" value="%s"/>' % alpha
    if illum in (4, 6, 7, 9):  # Pm does not make a dielectric a metal
        inner = ('<bsdf type="%sdielectric">%s<float name="int_ior" value="%s"/>'
                 '<float name="ext_ior" value="1"/></bsdf>'
                 % ("rough" if rough else "", ggx if rough else "", m["Ni"]))
        return inner, m.get("Ke")
    if metal:  # a conductor of the base colour
        inner = ('<bsdf type="%sconductor">%s%s</bsdf>'
                 % ("rough" if rough else "", ggx if rough else "", kd_xml % "specular_reflectance"))
    elif illum == 2 and "Ks" in m:
        inner = ('<bsdf type="%splastic">%s%s'
                 '<rgb name="specular_reflectance" value="%s"/><float name="int_ior" value="%s"/>'
                 '<float name="ext_ior" value="1"/></bsdf>'
                 % ("rough" if rough else "", ggx if rough else "", kd_xml % "diffuse_reflectance",
                    m["Ks"], m.get("Ni", "1.5")))
    elif illum in (3, 5, 8):
        inner = ('<bsdf type="%sconductor">%s<rgb name="specular_reflectance" value="%s"/></bsdf>'
                 % ("rough" if rough else "", ggx if rough else "", m["Ks"]))
    else:
        inner = '<bsdf type="diffuse">%s</bsdf>' % (kd_xml % "reflectance")
    return '<bsdf type="twosided">%s</bsdf>' % inner, m.get("Ke")


def write_mitsuba(name, groups, materials, film, camera, depth, comment):
    """NAME.xml: the scene for Mitsuba 3, read by smallmlt as the .scene."""
    c = camera.split()
    mats = parse_mtl(materials)
    with open(os.path.join(HERE, name + ".xml"), "w") as f:
        f.write('<?xml version="1.0"?>\n<!-- %s\n     generated by scenes/generate.py -->\n'
                '<scene version="3.0.0">\n' % comment)
        f.write('    <integrator type="path"><integer name="max_depth" value="%d"/></integrator>\n'
                % (depth + 1))
        f.write('    <sensor type="perspective">\n'
                '        <float name="fov" value="%s"/><string name="fov_axis" value="y"/>\n'
                '        <transform name="to_world"><lookat origin="%s" target="%s" up="%s"/>'
                '</transform>\n'
                '        <film type="hdrfilm"><integer name="width" value="%d"/>'
                '<integer name="height" value="%d"/><rfilter type="box"/></film>\n'
                '    </sensor>\n' % (c[9], " ".join(c[0:3]), " ".join(c[3:6]), " ".join(c[6:9]),
                                     film[0], film[1]))
        for mat, rel, smooth in groups:
            bsdf, ke = mitsuba_bsdf(mats[mat])
            f.write('    <shape type="obj"><string name="filename" value="%s"/>\n' % rel)
            if not smooth:
                f.write('        <boolean name="face_normals" value="true"/>\n')
            f.write("        %s\n" % bsdf)
            if ke is not None and any(float(x) > 0 for x in ke.split()):
                f.write('        <emitter type="area"><rgb name="radiance" value="%s"/>'
                        '</emitter>\n' % ke)
            f.write("    </shape>\n")
        f.write("</scene>\n")


def write_scene(name, mesh, materials, film, camera, depth, comment):
    """NAME.scene and NAME.mtl, the meshes NAME/MATERIAL.obj, and NAME.xml."""
    groups = mesh.write(name, "../%s.mtl" % name)
    with open(os.path.join(HERE, name + ".mtl"), "w") as f:
        f.write("# generated by scenes/generate.py\n" + materials)
    with open(os.path.join(HERE, name + ".scene"), "w") as f:
        f.write("# %s\n# generated by scenes/generate.py\n" % comment)
        f.write("film    %d %d\n" % film)
        f.write("camera  %s\n" % camera)
        f.write("depth   %d\n" % depth)
        for _, rel, _ in groups:
            f.write("mesh    %s\n" % rel)
    write_mitsuba(name, groups, materials, film, camera, depth, comment)


CAMERA_FRONT = "0 1 3.4   0 1 0   0 1 0   40"


def cornell():
    m = Mesh()
    cornell_walls(m)
    m.quad("light", (0, 1.999, 0), (0, 0, 0.25), (0.25, 0, 0), (0, -1, 0))
    m.rotated_block("white", (0.33, 0, 0.3), (0.3, 0.3), 0.6, -18)
    m.rotated_block("white", (-0.35, 0, -0.3), (0.3, 0.3), 1.2, 17)
    mats = CORNELL_MATERIALS + "newmtl light\nKd 0.78 0.78 0.78\nKe 17 12 4\n"
    write_scene("cornell", m, mats, (512, 512), CAMERA_FRONT, 8,
                "cornell: the diffuse Cornell box with two blocks")


def water_height(x, z):
    return 0.9 + 0.025 * math.sin(7.0 * x + 2.0 * z) + 0.02 * math.sin(5.0 * z - 3.0 * x + 1.0)


def water_normal(x, z):
    """The normal of the surface y = water_height(x, z): (-dh/dx, 1, -dh/dz)."""
    dx = 0.025 * 7.0 * math.cos(7.0 * x + 2.0 * z) - 0.02 * 3.0 * math.cos(5.0 * z - 3.0 * x + 1.0)
    dz = 0.025 * 2.0 * math.cos(7.0 * x + 2.0 * z) + 0.02 * 5.0 * math.cos(5.0 * z - 3.0 * x + 1.0)
    return normalize((-dx, 1.0, -dz))


def water(m, smooth=False):
    """Water filling the box to about 0.9: a closed mesh (front faces
    outward) inset slightly from the walls, its surface in waves; `smooth`:
    with the waves' exact normals at its vertices (shading normals)."""
    n, lo, hi, bottom = 32, -0.999, 0.999, 0.001
    xs = [lo + (hi - lo) * i / n for i in range(n + 1)]
    top = [[(x, water_height(x, z), z) for x in xs] for z in xs]
    for j in range(n):
        for i in range(n):
            a, b, c, d = top[j][i], top[j][i + 1], top[j + 1][i + 1], top[j + 1][i]
            na, nb, nc, nd = (water_normal(p[0], p[2]) if smooth else None for p in (a, b, c, d))
            m.tri("water", a, b, c, facing=(0, 1, 0), normals=(na, nb, nc) if smooth else None)
            m.tri("water", a, c, d, facing=(0, 1, 0), normals=(na, nc, nd) if smooth else None)
    m.quad("water", (0, bottom, 0), (0, 0, (hi - lo) / 2), ((hi - lo) / 2, 0, 0), (0, -1, 0))
    edges = [([top[0][i] for i in range(n + 1)], (0, 0, -1)),
             ([top[n][i] for i in range(n + 1)], (0, 0, 1)),
             ([top[j][0] for j in range(n + 1)], (-1, 0, 0)),
             ([top[j][n] for j in range(n + 1)], (1, 0, 0))]
    for edge, out in edges:
        for k in range(n):
            p, q = edge[k], edge[k + 1]
            pb, qb = (p[0], bottom, p[2]), (q[0], bottom, q[2])
            m.tri("water", pb, qb, q, facing=out)
            m.tri("water", pb, q, p, facing=out)


def water_box(light, half_x, half_z, smooth=False):
    """The box with water, under a light on the ceiling of half-extents
    half_x by half_z: the mesh and the materials, `light` being the light's
    MTL statements."""
    m = Mesh()
    cornell_walls(m)
    m.quad("light", (0, 1.999, 0), (0, 0, half_z), (half_x, 0, 0), (0, -1, 0))
    water(m, smooth)
    return m, CORNELL_MATERIALS + "newmtl light\n" + light + "newmtl water\nillum 7\nNi 1.33\n"


def cornell_water():
    m, mats = water_box("Kd 0.78 0.78 0.78\nKe 50 50 50\n", 0.18, 0.18)
    write_scene("cornell-water", m, mats, (512, 512), CAMERA_FRONT, 24,
                "cornell-water: the box half-filled with water (index 1.33) under a small "
                "light; caustics on the floor")


def water_spark():
    # After Tungsten's example scene water-caustic (a light of 1 cm x 0.8 cm
    # and radiance about 5e5 over water): here the radiance is 1e5, so that
    # the light has about the power of cornell-water's and the box is
    # exposed alike. The camera sees the light directly, in a pixel or two
    # of the 160 x 90 film, 10^5 times display white; all else is lit by it,
    # under the water through the waves.
    m, mats = water_box("Kd 0 0 0\nKe 100000 100000 100000\n", 0.005, 0.004)
    write_scene("water-spark", m, mats, (160, 90), CAMERA_FRONT, 7,
                "water-spark: the box half-filled with water under a 1 cm light of radiance "
                "1e5 that the camera sees directly")


def cornell_glass():
    m = Mesh()
    cornell_walls(m)
    m.quad("light", (0, 1.999, 0), (0, 0, 0.2), (0.2, 0, 0), (0, -1, 0))
    m.sphere("glass", (0.25, 0.5, 0.1), 0.5, subdivisions=4)
    m.rotated_block("white", (-0.5, 0, -0.45), (0.25, 0.25), 1.0, 20)
    mats = CORNELL_MATERIALS + ("newmtl light\nKd 0.78 0.78 0.78\nKe 40 40 40\n"
                                "newmtl glass\nillum 7\nNi 1.5\n")
    write_scene("cornell-glass", m, mats, (512, 512), CAMERA_FRONT, 16,
                "cornell-glass: a glass sphere (index 1.5) and its caustic")


def tiny_caustic():
    m = Mesh()
    cornell_walls(m)
    m.quad("light", (0, 1.999, 0), (0, 0, 0.25), (0.25, 0, 0), (0, -1, 0))
    # A ball lens (focal length 1.5 r from its centre) images a 1 cm light
    # 0.45 above its centre onto the floor 0.45 below it: 2/0.45 = 1/0.225.
    # The light is seen from the floor below only through the glass, so only
    # paths that scatter off the floor and happen to reach it carry the
    # caustic: rare, and hundreds of times brighter than the floor around it.
    m.sphere("glass", (0.3, 0.45, 0.1), 0.15, subdivisions=4)
    m.quad("spark", (0.3, 0.9, 0.1), (0, 0, 0.005), (0.005, 0, 0), (0, -1, 0))
    m.rotated_block("white", (-0.45, 0, -0.4), (0.25, 0.25), 0.9, 20)
    mats = CORNELL_MATERIALS + ("newmtl light\nKd 0.78 0.78 0.78\nKe 17 12 4\n"
                                "newmtl spark\nKd 0 0 0\nKe 20000 20000 20000\n"
                                "newmtl glass\nillum 7\nNi 1.5\n")
    write_scene("tiny-caustic", m, mats, (512, 512), CAMERA_FRONT, 8,
                "tiny-caustic: a 1 cm light focused by a glass ball into a tiny, very bright "
                "caustic on the floor: chains that find it get stuck")


def furnace():
    m = Mesh()
    m.box("wall", (-1, -1, -1), (1, 1, 1), inward=True)
    mats = "newmtl wall\nKd 0.5 0.5 0.5\nKe 1 1 1\n"
    write_scene("furnace", m, mats, (64, 64), "0 0 0   0 0 -1   0 1 0   60", 24,
                "furnace: a closed box whose every face has Kd 0.5 and Ke 1; the radiance "
                "everywhere is the sum of 0.5^i for i = 0..depth")


def ajar():
    m = Mesh()
    # One closed hall x in [-1, 2]; a wall at x = 1 splits it into the room
    # (x < 1) and a lit closet (x > 1), joined only by a slit, the door ajar.
    m.box("white", (-1, 0, -1), (2, 2, 1), inward=True)
    gap_lo, gap_hi = -0.03, 0.03
    m.quad("white", (1, 1, (-1 + gap_lo) / 2), (0, 0, (gap_lo + 1) / 2), (0, 1, 0), (-1, 0, 0))
    m.quad("white", (1, 1, (gap_hi + 1) / 2), (0, 0, (1 - gap_hi) / 2), (0, 1, 0), (-1, 0, 0))
    m.quad("light", (1.6, 1.999, 0), (0, 0, 0.3), (0.3, 0, 0), (0, -1, 0))
    m.rotated_block("red", (-0.2, 0, -0.3), (0.25, 0.25), 0.7, 25)
    mats = ("newmtl white\nKd 0.75 0.75 0.75\nnewmtl red\nKd 0.63 0.065 0.05\n"
            "newmtl light\nKd 0.78 0.78 0.78\nKe 60 60 60\n")
    write_scene("ajar", m, mats, (512, 512), "-0.9 1.3 0.9   0.6 0.5 -0.3   0 1 0   65", 16,
                "ajar: light reaches the room only through a narrow slit from a lit closet")


def cornell_water_smooth():
    m, mats = water_box("Kd 0.78 0.78 0.78\nKe 50 50 50\n", 0.18, 0.18, smooth=True)
    write_scene("cornell-water-smooth", m, mats, (512, 512), CAMERA_FRONT, 24,
                "cornell-water-smooth: cornell-water with the waves' exact normals at the "
                "water's vertices (shading normals): a smooth surface and its caustic")


def veach_mis():
    # After Veach's multiple importance sampling scene: four plates of rough
    # metal, smoothest in front, each turned to mirror the row of lights
    # toward the camera; four spheres of radius 0.03 to 0.5 of equal power
    # (radiance ~ 1 / r^2). Light sampling wins on the rough plates and the
    # small lights, BSDF sampling on the smooth plates and the large ones.
    m = Mesh()
    eye, lights_at = (0.0, 2.0, 6.0), (0.0, 2.5, -2.5)
    m.quad("backdrop", (0, -0.2, 0), (0, 0, 6), (6, 0, 0), (0, 1, 0))
    m.quad("backdrop", (0, 3, -4), (6, 0, 0), (0, 3.2, 0), (0, 0, 1))
    for k, (z, rough) in enumerate(((1.6, "0.070711"), (0.8, "0.141421"),
                                     (0.0, "0.223607"), (-0.8, "0.316228"))):
        c = (0.0, 0.1 + 0.22 * k, z)
        n = normalize(add(normalize(sub(eye, c)), normalize(sub(lights_at, c))))
        u = (1.8, 0.0, 0.0)
        v = scale(normalize(cross(n, u)), 0.32)
        m.quad("plate%d" % k, c, u, v, n)
    for k, r in enumerate((0.03, 0.1, 0.25, 0.5)):
        m.sphere("lamp%d" % k, (-2.1 + 1.4 * k, lights_at[1], lights_at[2]), r, subdivisions=2)
    mats = "newmtl backdrop\nKd 0.2 0.2 0.2\n"
    for k, rough in enumerate(("0.070711", "0.141421", "0.223607", "0.316228")):
        mats += ("newmtl plate%d\n# alpha = Pr^2 = %.3g\nillum 3\nKs 0.85 0.85 0.85\nPr %s\n"
                 % (k, float(rough) ** 2, rough))
    for k, r in enumerate((0.03, 0.1, 0.25, 0.5)):
        ke = 0.8 / (r * r)
        mats += "newmtl lamp%d\nKd 0 0 0\nKe %g %g %g\n" % (k, ke, ke * 0.9, ke * 0.8)
    write_scene("veach-mis", m, mats, (512, 384), "0 2 6   0 0.7 0   0 1 0   38", 4,
                "veach-mis: four rough-metal plates (alpha 0.005 to 0.1) lit by four spheres "
                "of equal power and radii 0.03 to 0.5")


def cornell_glossy():
    # Plastic walls, rough-metal blocks and a checkered plastic floor; the
    # floor's tiles are geometry (two materials).
    m = Mesh()
    n = 8
    for i in range(n):
        for j in range(n):
            c = (-1 + (2 * i + 1) / n, 0, -1 + (2 * j + 1) / n)
            m.quad("tile%d" % ((i + j) % 2), c, (0, 0, 1.0 / n), (1.0 / n, 0, 0), (0, 1, 0))
    m.quad("white", (0, 2, 0), (0, 0, 1), (1, 0, 0), (0, -1, 0))    # ceiling
    m.quad("white", (0, 1, -1), (1, 0, 0), (0, 1, 0), (0, 0, 1))    # back
    m.quad("red", (-1, 1, 0), (0, 0, 1), (0, 1, 0), (1, 0, 0))      # left
    m.quad("green", (1, 1, 0), (0, 0, 1), (0, 1, 0), (-1, 0, 0))    # right
    m.quad("light", (0, 1.999, 0), (0, 0, 0.25), (0.25, 0, 0), (0, -1, 0))
    m.rotated_block("gold", (0.33, 0, 0.3), (0.3, 0.3), 0.6, -18)
    m.rotated_block("steel", (-0.35, 0, -0.3), (0.3, 0.3), 1.2, 17)
    mats = ("newmtl white\nillum 2\nKd 0.72 0.72 0.72\nKs 0.5 0.5 0.5\nNi 1.5\nPr 0.5\n"
            "newmtl red\nillum 2\nKd 0.6 0.06 0.05\nKs 0.5 0.5 0.5\nNi 1.5\nPr 0.5\n"
            "newmtl green\nillum 2\nKd 0.13 0.43 0.09\nKs 0.5 0.5 0.5\nNi 1.5\nPr 0.5\n"
            "newmtl tile0\nillum 2\nKd 0.7 0.7 0.65\nKs 1 1 1\nNi 1.5\nPr 0.2\n"
            "newmtl tile1\nillum 2\nKd 0.1 0.1 0.12\nKs 1 1 1\nNi 1.5\nPr 0.2\n"
            "newmtl gold\nillum 3\nKs 0.9 0.7 0.35\nPr 0.45\n"
            "newmtl steel\nillum 3\nKs 0.75 0.75 0.75\nPr 0.3\n"
            "newmtl light\nKd 0.78 0.78 0.78\nKe 17 12 4\n")
    write_scene("cornell-glossy", m, mats, (512, 512), CAMERA_FRONT, 8,
                "cornell-glossy: plastic walls, rough-metal blocks and a checkered plastic floor")


def write_png(path, width, height, pixel):
    """An 8-bit RGB PNG; pixel(x, y) gives (r, g, b) in 0..255."""
    rows = b"".join(b"\x00" + bytes(c for x in range(width) for c in pixel(x, y))
                    for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(rows, 9)))
        f.write(chunk(b"IEND", b""))


def blender_export():
    """A model written the way Blender 4.x's OBJ exporter writes one (with
    its PBR extension): objects, per-corner texture coordinates and
    normals, smoothing groups, quads, and an image texture."""
    write_png(os.path.join(HERE, "blender-export-checker.png"), 64, 64,
              lambda x, y: (200, 190, 170) if (x // 8 + y // 8) % 2 else (60, 70, 90))
    out = ["# Blender 4.1.1", "# www.blender.org", "mtllib blender-export.mtl"]
    counts = {"v": 0, "vt": 0, "vn": 0}

    def emit(kind, vals):
        out.append(kind + " " + " ".join("%.6f" % c for c in vals))
        counts[kind] += 1
        return counts[kind]

    def flat_object(name, mat, quads):
        out.append("o " + name)
        faces = []
        for q in quads:
            vs = [emit("v", p) for p in q]
            ts = [emit("vt", t) for t in ((0, 0), (1, 0), (1, 1), (0, 1))]
            n = emit("vn", normalize(cross(sub(q[1], q[0]), sub(q[2], q[0]))))
            faces.append(" ".join("%d/%d/%d" % (v, t, n) for v, t in zip(vs, ts)))
        out.append("s 0")
        out.append("usemtl " + mat)
        out.extend("f " + f for f in faces)

    floor = [(-3, 0, 3), (3, 0, 3), (3, 0, -3), (-3, 0, -3)]
    flat_object("Plane", "Floor", [floor])
    flat_object("Wall", "Wall", [[(-3, 0, -2.5), (3, 0, -2.5), (3, 3, -2.5), (-3, 3, -2.5)]])
    lo, hi = (0.3, 0.0, -0.6), (1.0, 0.7, 0.1)
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    cube = [[(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
            [(x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0)],
            [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],
            [(x1, y0, z1), (x1, y0, z0), (x1, y1, z0), (x1, y1, z1)],
            [(x0, y1, z1), (x1, y1, z1), (x1, y1, z0), (x0, y1, z0)],
            [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)]]
    flat_object("Cube", "Material", cube)
    flat_object("Area", "Emission", [[(-0.6, 2.6, 0.6), (-0.6, 2.6, -0.6), (0.6, 2.6, -0.6),
                                      (0.6, 2.6, 0.6)]])
    # A UV sphere, smooth shaded: one normal and texture coordinate per vertex.
    out.append("o Sphere")
    centre, radius, rings, segs = (-0.7, 0.55, 0.0), 0.55, 12, 24
    grid = {}
    for i in range(rings + 1):
        th = math.pi * i / rings
        for j in range(segs + 1):
            ph = 2 * math.pi * j / segs
            d = (math.sin(th) * math.cos(ph), math.cos(th), -math.sin(th) * math.sin(ph))
            grid[i, j] = (emit("v", add(centre, scale(d, radius))),
                          emit("vt", (j / segs, 1 - i / rings)), emit("vn", d))
    out.append("s 1")
    out.append("usemtl Metal")
    for i in range(rings):
        for j in range(segs):
            corners = [grid[i, j], grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]]
            if i == 0:
                corners = corners[:3]  # the poles' triangles
            elif i == rings - 1:
                corners = corners[:2] + corners[3:]
            out.append("f " + " ".join("%d/%d/%d" % c for c in corners))
    with open(os.path.join(HERE, "blender-export.obj"), "w") as f:
        f.write("\n".join(out) + "\n")
    groups = split_objects(out, "blender-export")
    pbr = "Ps 0.000000\nPc 0.000000\nPcr 0.030000\naniso 0.000000\nanisor 0.000000\n"
    mtl = ("# Blender 4.1.1 MTL File: 'None'\n# www.blender.org\n\n"
           "newmtl Emission\nPr 0.500000\nKd 0.000000 0.000000 0.000000\n"
           "Ks 0.500000 0.500000 0.500000\nKe 12.000000 12.000000 12.000000\nNi 1.450000\n"
           "d 1.000000\nillum 2\nPm 0.000000\n" + pbr + "\n"
           "newmtl Floor\nPr 0.400000\nKd 0.800000 0.800000 0.800000\n"
           "Ks 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\n"
           "d 1.000000\nillum 2\nPm 0.000000\n" + pbr +
           "map_Kd blender-export-checker.png\n\n"
           "newmtl Material\nPr 0.500000\nKd 0.800000 0.800000 0.800000\n"
           "Ks 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\n"
           "d 1.000000\nillum 2\nPm 0.000000\n" + pbr + "\n"
           "newmtl Metal\nPr 0.250000\nKd 0.900000 0.640000 0.300000\n"
           "Ks 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\n"
           "d 1.000000\nillum 3\nPm 1.000000\n" + pbr + "\n"
           "newmtl Wall\nPr 0.900000\nKd 0.600000 0.600000 0.600000\n"
           "Ks 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\n"
           "d 1.000000\nillum 2\nPm 0.000000\n" + pbr)
    with open(os.path.join(HERE, "blender-export.mtl"), "w") as f:
        f.write(mtl)
    with open(os.path.join(HERE, "blender-export.scene"), "w") as f:
        f.write("# blender-export: a model as Blender 4.x's OBJ exporter writes it (PBR "
                "extension, vn, vt, s, a texture), its files unedited\n"
                "# generated by scenes/generate.py\n"
                "film    512 384\ncamera  0 1.5 4.2   0 0.6 0   0 1 0   40\ndepth   8\n"
                "mesh    blender-export.obj\n")
    write_mitsuba("blender-export", groups, mtl, (512, 384), "0 1.5 4.2   0 0.6 0   0 1 0   40", 8,
                  "blender-export: blender-export.obj's objects, one file each")


def split_objects(lines, name):
    """Writes each object (`o`) of OBJ lines to NAME/OBJECT.obj, its indices
    made the file's own; each object has one material. Returns the groups
    write_mitsuba takes: (material, file, smooth), smooth (the normals are
    the file's) throughout."""
    os.makedirs(os.path.join(HERE, name), exist_ok=True)
    objects, seen = [], {"v": 0, "vt": 0, "vn": 0}
    for line in lines:
        t = line.split()
        if t[0] == "o":
            objects.append({"name": t[1], "lines": [line], "base": dict(seen), "mat": None})
        elif not objects:
            continue  # the header and mtllib: the shape's BSDF is the material
        elif t[0] in seen:
            seen[t[0]] += 1
            objects[-1]["lines"].append(line)
        elif t[0] == "usemtl":
            objects[-1]["mat"] = t[1]
        elif t[0] == "f":
            b = objects[-1]["base"]
            corners = ["/".join(str(int(i) - b[k]) for i, k in zip(c.split("/"), ("v", "vt", "vn")))
                       for c in t[1:]]
            objects[-1]["lines"].append("f " + " ".join(corners))
        else:
            objects[-1]["lines"].append(line)
    groups = []
    for o in objects:
        rel = "%s/%s.obj" % (name, o["name"])
        with open(os.path.join(HERE, rel), "w") as f:
            f.write("# %s of %s.obj, generated by scenes/generate.py\n" % (o["name"], name))
            f.write("\n".join(o["lines"]) + "\n")
        groups.append((o["mat"], rel, True))
    return groups


if __name__ == "__main__":
    cornell()
    cornell_water()
    cornell_water_smooth()
    veach_mis()
    cornell_glossy()
    blender_export()
    water_spark()
    cornell_glass()
    tiny_caustic()
    furnace()
    ajar()
