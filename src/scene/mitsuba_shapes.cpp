#include "scene/mitsuba_shapes.hpp"

#include "base/error.hpp"
#include "scene/text_parse.hpp"

#include <cmath>
#include <cstring>
#include <map>
#include <tuple>

namespace smallmlt {

namespace {

struct Vertex {
    Vec3 p, n;
    float u = 0, v = 0; // Mitsuba's texture coordinates: v = 0 is the image's first row
};

// A triangle of object-space vertices; `smooth`: the vertices' normals shade.
void push(Scene& scene, std::uint32_t material, const Vertex& a, const Vertex& b, const Vertex& c,
          bool smooth) {
    SceneTriangle t = SceneTriangle::flat(a.p, b.p, c.p, material);
    const Vertex* v[3] = {&a, &b, &c};
    const Vec3 flat = t.flat_normal();
    for (int k = 0; k < 3; ++k) {
        t.n[k] = smooth ? v[k]->n : flat;
        t.uv[k][0] = v[k]->u;
        t.uv[k][1] = 1 - v[k]->v; // smallmlt's v = 1 is the first row
    }
    t.smooth = smooth;
    scene.triangles.push_back(t);
}

// The four corners of [-1, 1]^2 at z = 0, normal +z, uv = ((x + 1)/2, (y + 1)/2).
void add_rectangle(Scene& scene, std::uint32_t m, const Mat4& to_local) {
    Vertex c[4];
    const float xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; ++i) {
        c[i].p = to_local.point({xy[i][0], xy[i][1], 0});
        c[i].u = (xy[i][0] + 1) / 2;
        c[i].v = (xy[i][1] + 1) / 2;
    }
    push(scene, m, c[0], c[1], c[2], false);
    push(scene, m, c[0], c[2], c[3], false);
}

void add_cube(Scene& scene, std::uint32_t m) {
    // Each face: the rectangle turned to face +-x, +-y, +-z, at distance 1.
    const Mat4 faces[6] = {
        Mat4::translate(0, 0, 1),
        Mat4::rotate(0, 1, 0, 180) * Mat4::translate(0, 0, 1),
        Mat4::rotate(0, 1, 0, 90) * Mat4::translate(0, 0, 1),
        Mat4::rotate(0, 1, 0, -90) * Mat4::translate(0, 0, 1),
        Mat4::rotate(1, 0, 0, -90) * Mat4::translate(0, 0, 1),
        Mat4::rotate(1, 0, 0, 90) * Mat4::translate(0, 0, 1),
    };
    for (const Mat4& f : faces)
        add_rectangle(scene, m, f);
}

// Unit disk at z = 0, normal +z; uv = (r, phi / 2 pi).
void add_disk(Scene& scene, std::uint32_t m) {
    const int n = kCurveSegments;
    const double step = 2 * M_PI / n;
    const double r = std::sqrt(step / std::sin(step)); // the polygon's area is pi
    Vertex centre;
    for (int i = 0; i < n; ++i) {
        Vertex a, b;
        a.p = {float(r * std::cos(i * step)), float(r * std::sin(i * step)), 0};
        b.p = {float(r * std::cos((i + 1) * step)), float(r * std::sin((i + 1) * step)), 0};
        a.u = b.u = 1;
        a.v = float(i) / n;
        b.v = float(i + 1) / n;
        centre.v = (a.v + b.v) / 2;
        push(scene, m, centre, a, b, false);
    }
}

// Unit sphere; uv = (phi / 2 pi, theta / pi), theta from +z.
void add_sphere(Scene& scene, std::uint32_t m) {
    const int nu = kCurveSegments, nv = kSphereRings;
    auto at = [&](int i, int j, double r) {
        double theta = M_PI * j / nv, phi = 2 * M_PI * i / nu;
        Vertex v;
        v.n = {float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
               float(std::cos(theta))};
        v.p = v.n * float(r);
        v.u = float(i) / nu;
        v.v = float(j) / nv;
        return v;
    };
    // The mesh's area at radius 1, then the radius that makes it 4 pi.
    double area = 0;
    for (int pass = 0; pass < 2; ++pass) {
        const double r = pass == 0 ? 1.0 : std::sqrt(4 * M_PI / area);
        for (int j = 0; j < nv; ++j)
            for (int i = 0; i < nu; ++i) {
                Vertex a = at(i, j, r), b = at(i, j + 1, r), c = at(i + 1, j + 1, r),
                       d = at(i + 1, j, r);
                if (pass == 0) {
                    if (j > 0) area += 0.5 * length(cross(b.p - a.p, d.p - a.p));
                    if (j < nv - 1) area += 0.5 * length(cross(c.p - b.p, d.p - b.p));
                    continue;
                }
                if (j > 0) push(scene, m, a, b, d, true);
                if (j < nv - 1) push(scene, m, b, c, d, true);
            }
    }
}

// Angle-weighted vertex normals (Thuermer and Wuethrich 1998, as Mitsuba
// computes them) for the triangles from `first` on, at shared positions.
void vertex_normals(Scene& scene, std::size_t first) {
    auto key = [](Vec3 p) { return std::make_tuple(p.x, p.y, p.z); };
    std::map<std::tuple<float, float, float>, Vec3> sums;
    for (std::size_t t = first; t < scene.triangles.size(); ++t) {
        const SceneTriangle& tri = scene.triangles[t];
        const Vec3 face = tri.flat_normal();
        for (int k = 0; k < 3; ++k) {
            Vec3 e1 = normalize(tri.v[(k + 1) % 3] - tri.v[k]);
            Vec3 e2 = normalize(tri.v[(k + 2) % 3] - tri.v[k]);
            float angle = std::acos(std::clamp(dot(e1, e2), -1.0f, 1.0f));
            Vec3& s = sums[key(tri.v[k])];
            s = s + face * angle;
        }
    }
    for (std::size_t t = first; t < scene.triangles.size(); ++t) {
        SceneTriangle& tri = scene.triangles[t];
        if (tri.smooth) continue;
        for (int k = 0; k < 3; ++k) {
            Vec3 s = sums[key(tri.v[k])];
            if (length(s) > 0) tri.n[k] = normalize(s);
        }
        tri.smooth = true;
    }
}

// An obj or ply mesh. The readers store v as the file has it, and v = 1 is
// the top row here: Mitsuba's flip_tex_coords (default true for obj, false
// for ply) reads v = 1 - v_file, which is that; without it Mitsuba reads
// v_file as is, so v is flipped here.
void add_mesh(const XmlObject& o, std::uint32_t m, Scene& scene) {
    const bool obj = o.type == "obj";
    std::string file = xml_string(o, "filename", "");
    if (file.empty())
        throw input_error(o.where.file, o.where.line, "shape '" + o.type + "' needs a 'filename'");
    std::string path = file[0] == '/' ? file : dir_of(o.where.file) + file;
    std::size_t first = scene.triangles.size();
    if (obj)
        load_obj_geometry(path, o.where.str(), m, scene);
    else
        load_ply_geometry(path, o.where.str(), m, scene);
    const bool face_normals = xml_bool(o, "face_normals", false);
    const bool flip_uv = xml_bool(o, "flip_tex_coords", obj);
    for (std::size_t t = first; t < scene.triangles.size(); ++t) {
        SceneTriangle& tri = scene.triangles[t];
        if (face_normals && tri.smooth) {
            const Vec3 flat = tri.flat_normal();
            for (Vec3& n : tri.n)
                n = flat;
            tri.smooth = false;
        }
        if (!flip_uv)
            for (auto& uv : tri.uv)
                uv[1] = 1 - uv[1];
    }
    if (!face_normals) vertex_normals(scene, first);
}

} // namespace

void add_mitsuba_shape(const XmlObject& o, std::uint32_t material, Scene& scene) {
    const std::size_t first = scene.triangles.size();
    Mat4 to_world = xml_transform(o, "to_world");
    if (o.type == "obj" || o.type == "ply") {
        add_mesh(o, material, scene);
    } else if (o.type == "rectangle") {
        add_rectangle(scene, material, Mat4());
    } else if (o.type == "cube") {
        add_cube(scene, material);
    } else if (o.type == "disk") {
        add_disk(scene, material);
    } else if (o.type == "sphere") {
        Vec3 c = xml_point(o, "center", {0, 0, 0});
        double r = xml_float(o, "radius", 1);
        if (!(r > 0))
            throw input_error(o.where.file, o.where.line, "sphere: 'radius' must be positive");
        to_world = to_world * Mat4::translate(c.x, c.y, c.z) * Mat4::scale(r, r, r);
        add_sphere(scene, material);
    } else {
        throw input_error(o.where.file, o.where.line,
                          "shape '" + o.type +
                              "' is not read (obj, ply, rectangle, cube, disk and sphere are)");
    }
    if (!(std::abs(to_world.det3()) > 0))
        throw input_error(o.where.file, o.where.line, "'to_world' of the shape is singular");
    const bool flip = xml_bool(o, "flip_normals", false);
    const bool identity = to_world.is_identity();
    for (std::size_t t = first; t < scene.triangles.size(); ++t) {
        SceneTriangle& tri = scene.triangles[t];
        if (!identity) // (an identity keeps a mesh's numbers as read)
            for (int k = 0; k < 3; ++k) {
                tri.v[k] = to_world.point(tri.v[k]);
                tri.n[k] = normalize(to_world.normal(tri.n[k]));
            }
        if (flip) {
            std::swap(tri.v[1], tri.v[2]);
            std::swap(tri.n[1], tri.n[2]);
            std::swap(tri.uv[1], tri.uv[2]);
            for (Vec3& n : tri.n)
                n = n * -1.0f;
        }
        if (!(length(cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0])) > 0)) {
            ++scene.dropped_degenerate;
            tri.material = ~0u; // removed below
        }
    }
    std::size_t out = first;
    for (std::size_t t = first; t < scene.triangles.size(); ++t)
        if (scene.triangles[t].material != ~0u) scene.triangles[out++] = scene.triangles[t];
    scene.triangles.resize(out);
}

} // namespace smallmlt
