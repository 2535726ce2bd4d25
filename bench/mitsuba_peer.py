"""Mitsuba 3 against smallmlt on scene files (run by bench/mitsuba.sh).

Per scene:
1. Agreement: REPLICAS renders by Mitsuba's path integrator and as many by
   smallmlt's path tracer (own seeds, AGREE_SPP samples per pixel, film
   AGREE_SIZE square); per 8x8-pixel region, Welch's t of the mean luminance,
   against the two-sided Student quantile at 0.01 over the regions
   (Bonferroni); and the two image means.
2. Equal time: Mitsuba, smallmlt PT and smallmlt MLT for SECONDS each at
   SIZE x SIZE, MSE and 8x8-block MSE on linear RGB against a smallmlt PT
   reference of REF_SECONDS; medians over SEEDS seeds. Mitsuba's time is its render call after a
   warm-up render has compiled its kernels; smallmlt's is its --time.

Rough plastic: Mitsuba 3's roughplastic takes the coat's inner reflectance
R as twice the plain mean of r(cos) cos over 64 equally spaced cosines;
smallmlt takes the integral (doc/RESULTS.md, "Mitsuba 3 as a peer"). Both
divide the diffuse base by 1 - R, so, unless PEER_RINT=mitsuba, Mitsuba's
copy of the scene has each roughplastic's diffuse_reflectance scaled by
(1 - R_mitsuba) / (1 - R_integral): R_mitsuba read from Mitsuba's own BSDF,
R_integral computed here from its definition. Both are printed.
"""
import math
import os
import re
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

import drjit as dr
import mitsuba as mi
import numpy as np

mi.set_variant("llvm_ad_rgb")

THREADS = int(os.environ.get("THREADS", "2"))
SIZE = int(os.environ.get("SIZE", "128"))
SECONDS = float(os.environ.get("SECONDS", "10"))
REPLICAS = int(os.environ.get("REPLICAS", "8"))
AGREE_SIZE = int(os.environ.get("AGREE_SIZE", "64"))
AGREE_SPP = int(os.environ.get("AGREE_SPP", "256"))
REF_SECONDS = int(os.environ.get("REF_SECONDS", "300"))
PEER_RINT = os.environ.get("PEER_RINT", "integral")
EQUAL_TIME = os.environ.get("EQUAL_TIME", "1") != "0"
SEEDS = int(os.environ.get("SEEDS", "3"))
OUT = os.path.join("bench", "results", "mitsuba")
CACHE = os.path.join("bench", "cache")
ALPHA = 0.01
BLOCK = 8

dr.set_thread_count(THREADS)


def read_pfm(path):
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            raise ValueError(path + ": not an RGB PFM")
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.fromfile(f, "<f4" if scale < 0 else ">f4").reshape(h, w, 3)
    return data[::-1].astype(np.float64)  # top row first


def luminance(img):
    return 0.2126 * img[..., 0] + 0.7152 * img[..., 1] + 0.0722 * img[..., 2]


def block_means(values, block):
    h, w = values.shape[:2]
    v = values[: h - h % block, : w - w % block]
    return v.reshape(h // block, block, w // block, block, *v.shape[2:]).mean(axis=(1, 3))


def student_quantile(p_two_sided, df):
    """t with P(|T| > t) = p, by bisection on the t density's integral."""
    def upper_tail(t):
        x = np.linspace(t, t + 60.0, 200001)
        pdf = (math.gamma((df + 1) / 2) / (math.sqrt(df * math.pi) * math.gamma(df / 2))
               * (1 + x * x / df) ** (-(df + 1) / 2))
        return float(np.trapezoid(pdf, x))
    lo, hi = 0.0, 100.0
    for _ in range(60):
        mid = (lo + hi) / 2
        if 2 * upper_tail(mid) > p_two_sided:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def fresnel(cos_i, eta):
    """Unpolarized Fresnel reflectance of a dielectric, index ratio eta."""
    sin2_t = (1 - cos_i * cos_i) / (eta * eta)
    cos_t = np.sqrt(np.maximum(0.0, 1 - sin2_t))
    with np.errstate(invalid="ignore", divide="ignore"):  # 0 / 0 at grazing, masked out
        r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t)
        r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t)
    return np.where(sin2_t >= 1, 1.0, np.nan_to_num(0.5 * (r_s * r_s + r_p * r_p), nan=1.0))


def smith_g1(wz, wm, alpha, beckmann):
    """Smith's G1 for a direction of cosine wz whose dot with the facet is wm."""
    tan2 = np.maximum(0.0, 1 - wz * wz) / np.maximum(wz * wz, 1e-300)
    if beckmann:
        a = 1 / np.maximum(alpha * np.sqrt(tan2), 1e-300)
        lam = np.where(a > 30, 0.0, 0.5 * (np.vectorize(math.erf)(a) - 1) + np.exp(-a * a) / (2 * a * math.sqrt(math.pi)))
    else:
        x = alpha * alpha * tan2
        lam = x / (2 * (np.sqrt(1 + x) + 1))
    return np.where(wm * wz > 0, 1 / (1 + lam), 0.0)


def inner_reflectance(ior, alpha, beckmann):
    """R = 2 * integral over cos of r(cos) cos, r(cos) the visible normals'
    mean of F(w.m, 1/ior) G1(reflected) from inside the coat: Gauss-Legendre
    on panels either side of the critical cosine, the visible normals on a
    midpoint grid of the distribution's inverted CDF."""
    nv, nphi = 512, 128
    v = (np.arange(nv) + 0.5) / nv
    u = 1 - (1 - v) ** 2
    tan2 = -alpha * alpha * np.log1p(-u) if beckmann else alpha * alpha * u / (1 - u)
    cz = 1 / np.sqrt(1 + tan2)
    sz = np.sqrt(tan2) * cz
    phi = (np.arange(nphi) + 0.5) * math.pi / nphi
    mx, my, mz = np.outer(sz, np.cos(phi)), np.outer(sz, np.sin(phi)), np.outer(cz, np.ones(nphi))
    jac = np.outer(2 * (1 - v) / cz, np.ones(nphi))

    def r(c):
        s = math.sqrt(max(0.0, 1 - c * c))
        wm = s * mx + c * mz
        rz = 2 * wm * mz - c
        g = np.where((wm > 0) & (rz > 0), fresnel(np.maximum(wm, 0), 1 / ior) * smith_g1(rz, wm, alpha, beckmann), 0)
        mean = (g * np.maximum(wm, 0) * jac).sum() / (nv * nphi)
        return float(smith_g1(np.array(c), np.array(c), alpha, beckmann)) / c * mean

    x, w = np.polynomial.legendre.leggauss(8)
    cos_c = math.sqrt(1 - 1 / (ior * ior))
    total = 0.0
    for lo, hi in ((0.0, cos_c), (cos_c, 1.0)):
        for p in range(8):
            a, b = lo + (hi - lo) * p / 8, lo + (hi - lo) * (p + 1) / 8
            for xi, wi in zip(x, w):
                c = a + (b - a) * (xi + 1) / 2
                total += wi * (b - a) / 2 * r(c) * c
    return 2 * total


def mitsuba_inner_reflectance(props):
    """Mitsuba's own R, read from its roughplastic: the linear base is
    d / (1 - R), the nonlinear one d / (1 - d R), so with d = 1 and d = 1/2
    their ratio q = (2 - R) / (1 - R)."""
    def base(nonlinear, d):
        bsdf = mi.load_dict(dict(props, type="roughplastic", nonlinear=nonlinear,
                                 diffuse_reflectance={"type": "rgb", "value": [d, d, d]},
                                 specular_reflectance={"type": "rgb", "value": [0.0, 0.0, 0.0]}))
        si = dr.zeros(mi.SurfaceInteraction3f)
        si.wi = mi.Vector3f(0, 0, 1)
        return float(bsdf.eval(mi.BSDFContext(), si, mi.Vector3f(0, 0, 1))[0][0])
    q = base(False, 1.0) / base(True, 0.5)
    return (q - 2) / (q - 1)


def peer_scene(xml_path, size, out_path, for_mitsuba, written):
    """A copy of the scene file with a size x size film, beside it (so that
    its relative paths hold); Mitsuba's copy with rough plastic's inner
    reflectance made the integral's (module doc). The files it writes are
    added to `written`."""
    text = open(xml_path).read()
    text = re.sub(r'(<integer name="width" value=")\d+', r"\g<1>%d" % size, text)
    text = re.sub(r'(<integer name="height" value=")\d+', r"\g<1>%d" % size, text)
    if for_mitsuba and PEER_RINT != "mitsuba" and "roughplastic" in text:
        root = ET.fromstring(text)
        if not root.get("version", "3").startswith("3"):
            sys.exit("%s: roughplastic in the 0.5/0.6 syntax is not corrected here (PEER_RINT=mitsuba "
                     "leaves it)" % xml_path)
        for bsdf in root.iter("bsdf"):
            if bsdf.get("type") == "roughplastic":
                correct_inner_reflectance(xml_path, bsdf, written)
        text = ET.tostring(root, encoding="unicode")
    with open(out_path, "w") as f:
        f.write(text)
    written.append(out_path)
    return out_path


_rint_cache = {}


def correct_inner_reflectance(xml_path, bsdf, written):
    values = {c.get("name"): c for c in bsdf}
    diffuse = values.get("diffuse_reflectance")
    texture = diffuse is not None and diffuse.tag == "texture"
    if diffuse is not None and diffuse.tag not in ("rgb", "spectrum", "float") and not (
            texture and diffuse.get("type") == "bitmap"
            and not any(c.get("name") == "raw" and c.get("value") == "true" for c in diffuse)):
        print("%s: a roughplastic's diffuse_reflectance other than a value or an sRGB bitmap is left "
              "as it is: Mitsuba's inner reflectance stays" % xml_path)
        return
    props = {"distribution": values["distribution"].get("value") if "distribution" in values else "beckmann",
             "alpha": float(values["alpha"].get("value")) if "alpha" in values else 0.1,
             "int_ior": float(values["int_ior"].get("value")) if "int_ior" in values else 1.49,
             "ext_ior": float(values["ext_ior"].get("value")) if "ext_ior" in values else 1.000277}
    key = tuple(sorted(props.items()))
    if key not in _rint_cache:
        r_mi = mitsuba_inner_reflectance(props)
        r_int = inner_reflectance(props["int_ior"] / props["ext_ior"], props["alpha"],
                                  props["distribution"] == "beckmann")
        _rint_cache[key] = (r_mi, r_int)
        print("roughplastic %s: inner reflectance Mitsuba %.5f, integral %.5f: Mitsuba's diffuse_reflectance "
              "scaled by %.5f" % (props, r_mi, r_int, (1 - r_mi) / (1 - r_int)), flush=True)
    r_mi, r_int = _rint_cache[key]
    k = (1 - r_mi) / (1 - r_int)
    if texture:  # the image as linear floats times k (Mitsuba filters in linear)
        name = next(c for c in diffuse if c.get("name") == "filename")
        src = os.path.join(os.path.dirname(xml_path), name.get("value"))
        bmp = mi.Bitmap(src).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32, srgb_gamma=False)
        out = os.path.join(os.path.dirname(xml_path), ".peer-%d.exr" % len(written))
        mi.Bitmap(np.array(bmp) * np.float32(k)).write(out)
        written.append(out)
        name.set("value", os.path.basename(out))
        return
    d = [float(x) for x in (diffuse.get("value") if diffuse is not None else "0.5").replace(",", " ").split()]
    d = [x * k for x in (d * 3 if len(d) == 1 else d)]
    if diffuse is None:
        diffuse = ET.SubElement(bsdf, "rgb", name="diffuse_reflectance")
    diffuse.set("value", " ".join("%.9g" % x for x in d))


def mitsuba_render(path, spp, seed):
    scene = mi.load_file(path)
    t0 = time.time()
    img = np.array(mi.render(scene, spp=spp, seed=seed), dtype=np.float64)
    return img[..., :3], time.time() - t0


def smallmlt_render(binary, path, args, out):
    cmd = [binary, "render", path, "--quiet", "--out", out] + args
    run = subprocess.run(cmd, stderr=subprocess.PIPE, text=True)
    if run.returncode != 0:
        sys.exit(run.stderr + "bench/mitsuba_peer.py: " + " ".join(cmd) + " failed")
    return read_pfm(out)


def cbox(path, size):
    """Mitsuba's own Cornell box (mi.cornell_box()) as a scene file, with a
    box filter (smallmlt's) and a size x size film."""
    d = mi.cornell_box()
    d["sensor"]["film"]["rfilter"] = {"type": "box"}
    d["sensor"]["film"]["width"] = d["sensor"]["film"]["height"] = size

    def value(name, v, pad):
        if isinstance(v, bool):
            return '%s<boolean name="%s" value="%s"/>\n' % (pad, name, str(v).lower())
        if isinstance(v, int):
            return '%s<integer name="%s" value="%d"/>\n' % (pad, name, v)
        if isinstance(v, float):
            return '%s<float name="%s" value="%r"/>\n' % (pad, name, v)
        if isinstance(v, str):
            return '%s<string name="%s" value="%s"/>\n' % (pad, name, v)
        if isinstance(v, mi.ScalarTransform4f):
            m = np.array(v.matrix).reshape(4, 4)
            return ('%s<transform name="%s"><matrix value="%s"/></transform>\n'
                    % (pad, name, " ".join("%r" % float(x) for x in m.flatten())))
        if isinstance(v, dict) and v.get("type") == "rgb":
            return '%s<rgb name="%s" value="%s"/>\n' % (pad, name, " ".join("%r" % float(x) for x in v["value"]))
        if isinstance(v, dict) and v.get("type") == "ref":
            return '%s<ref id="%s"/>\n' % (pad, v["id"])
        if isinstance(v, dict):
            return obj(name, v, pad)
        raise TypeError(name)

    tags = {"path": "integrator", "perspective": "sensor", "hdrfilm": "film", "independent": "sampler",
            "box": "rfilter", "diffuse": "bsdf", "rectangle": "shape", "cube": "shape", "area": "emitter"}

    def obj(key, v, pad, ident=None):
        tag = tags[v["type"]]
        s = '%s<%s type="%s"%s>\n' % (pad, tag, v["type"], ' id="%s"' % ident if ident else "")
        for k, x in v.items():
            if k != "type":
                s += value(k, x, pad + "    ")
        return s + "%s</%s>\n" % (pad, tag)

    text = '<scene version="3.0.0">\n'
    for k, v in d.items():
        if k != "type":
            text += obj(k, v, "    ", ident=k if v["type"] == "diffuse" else None)
    with open(path, "w") as f:
        f.write(text + "</scene>\n")
    return path


def agreement(binary, name, paths, tmp):
    path, mits_path = paths
    mits, ours = [], []
    for r in range(1, REPLICAS + 1):
        img, _ = mitsuba_render(mits_path, AGREE_SPP, r)
        mits.append(luminance(img))
        ours.append(luminance(smallmlt_render(
            binary, path, ["--method", "pt", "--spp", str(AGREE_SPP), "--seed", str(r)],
            os.path.join(tmp, "a.pfm"))))
    a = np.array([block_means(x, BLOCK) for x in mits]).reshape(REPLICAS, -1)
    b = np.array([block_means(x, BLOCK) for x in ours]).reshape(REPLICAS, -1)
    va, vb = a.var(axis=0, ddof=1) / REPLICAS, b.var(axis=0, ddof=1) / REPLICAS
    se = np.sqrt(va + vb)
    ok = se > 0
    t = np.zeros_like(se)
    t[ok] = (b.mean(axis=0) - a.mean(axis=0))[ok] / se[ok]
    df = (va + vb) ** 2 / (va ** 2 / (REPLICAS - 1) + vb ** 2 / (REPLICAS - 1) + 1e-300)
    regions = int(ok.sum())
    crit = student_quantile(ALPHA / regions, float(np.median(df[ok])))
    worst = int(np.argmax(np.abs(t)))
    ma, mb = a.mean(axis=1), b.mean(axis=1)  # image means per replica
    z_mean = (mb.mean() - ma.mean()) / math.sqrt(ma.var(ddof=1) / REPLICAS + mb.var(ddof=1) / REPLICAS)
    rel = (b.mean(axis=0)[worst] - a.mean(axis=0)[worst]) / max(a.mean(axis=0)[worst], 1e-30)
    return {
        "scene": name, "mitsuba_mean": ma.mean(), "pt_mean": mb.mean(), "mean_z": z_mean,
        "regions": regions, "max_abs_t": float(np.abs(t).max()), "critical_t": crit,
        "worst_region_rel_diff": rel, "agree": bool(np.abs(t).max() < crit and abs(z_mean) < crit),
    }


def equal_time(binary, name, paths, tmp):
    path, mits_path = paths
    ref_path = os.path.join(CACHE, "%s-xml-%dx%d-%ds.pfm" % (name, SIZE, SIZE, REF_SECONDS))
    if not os.path.exists(ref_path):
        print("rendering the reference %s (smallmlt PT, %d s)" % (ref_path, REF_SECONDS), flush=True)
        smallmlt_render(binary, path, ["--method", "pt", "--time", str(REF_SECONDS), "--seed", "987654321"], ref_path)
    ref = read_pfm(ref_path)
    def errors(img):
        return (float(((img - ref) ** 2).mean()),
                float(((block_means(img, BLOCK) - block_means(ref, BLOCK)) ** 2).mean()))

    runs = {"Mitsuba 3 path": [], "smallmlt PT": [], "smallmlt MLT": []}
    mitsuba_render(mits_path, 4, 1000)  # compiles the kernels
    _, t16 = mitsuba_render(mits_path, 16, 1001)
    spp = max(1, int(SECONDS / (t16 / 16)))
    for seed in range(1, SEEDS + 1):
        img, secs = mitsuba_render(mits_path, spp, seed)
        runs["Mitsuba 3 path"].append((secs,) + errors(img))
        for label, method in (("smallmlt PT", "pt"), ("smallmlt MLT", "mlt")):
            img = smallmlt_render(binary, path, ["--method", method, "--time", str(SECONDS), "--seed", str(seed)],
                                  os.path.join(tmp, "e.pfm"))
            runs[label].append((SECONDS,) + errors(img))
    # Medians over the seeds (the machine is shared: one slow run is noise).
    return [(label, float(np.median([r[0] for r in rs])), float(np.median([r[1] for r in rs])),
             float(np.median([r[2] for r in rs]))) for label, rs in runs.items()]


def main():
    binary = sys.argv[1]
    os.makedirs(OUT, exist_ok=True)
    os.makedirs(CACHE, exist_ok=True)
    print("Mitsuba %s (llvm_ad_rgb), %d threads; smallmlt %s" % (mi.__version__, THREADS, binary))
    report = []
    for arg in sys.argv[2:]:
        name = "cbox" if arg == "cbox" else os.path.splitext(os.path.basename(arg))[0]
        with tempfile.TemporaryDirectory() as tmp:
            copies = []  # files written beside the scene, removed after it
            try:
                if arg == "cbox":
                    src = (cbox(os.path.join(OUT, "cbox.xml"), SIZE),) * 2
                    small = (cbox(os.path.join(OUT, "cbox-agree.xml"), AGREE_SIZE),) * 2
                else:
                    def copy(size, suffix, for_mitsuba):
                        out = os.path.join(os.path.dirname(arg), ".peer-%s%s.xml" % (name, suffix))
                        return peer_scene(arg, size, out, for_mitsuba, copies)
                    src = (copy(SIZE, "", False), copy(SIZE, "-mitsuba", True))
                    small = (copy(AGREE_SIZE, "-agree", False), copy(AGREE_SIZE, "-agree-mitsuba", True))
                a = agreement(binary, name, small, tmp)
                print("%s: image mean PT %.6g, Mitsuba %.6g (z %+.2f); %d regions of %dx%d, largest |t| %.2f "
                      "(limit %.2f at %.2g, Bonferroni): %s; worst region PT/Mitsuba - 1 = %+.2f%%"
                      % (name, a["pt_mean"], a["mitsuba_mean"], a["mean_z"], a["regions"], BLOCK, BLOCK,
                         a["max_abs_t"], a["critical_t"], ALPHA, "agree" if a["agree"] else "DISAGREE",
                         100 * a["worst_region_rel_diff"]), flush=True)
                e = equal_time(binary, name, src, tmp) if EQUAL_TIME else []
                for label, secs, mse, bmse in e:
                    print("  %-14s %6.2f s  MSE %.4g  8x8-block MSE %.4g" % (label, secs, mse, bmse), flush=True)
                report.append((a, e))
            finally:
                for p in copies:
                    os.remove(p)
    with open(os.path.join(OUT, "summary.md"), "w") as f:
        f.write("| scene | PT / Mitsuba mean | mean z | largest region |t| (limit) | agree | "
                "MSE at %g s: Mitsuba / PT / MLT | 8x8 blocks |\n| --- | --- | --- | --- | --- | --- | --- |\n" % SECONDS)
        for a, e in report:
            f.write("| %s | %.4f | %+.2f | %.2f (%.2f) | %s | %s | %s |\n" % (
                a["scene"], a["pt_mean"] / a["mitsuba_mean"], a["mean_z"], a["max_abs_t"], a["critical_t"],
                "yes" if a["agree"] else "no", " / ".join("%.3g" % r[2] for r in e) or "(not run)",
                " / ".join("%.3g" % r[3] for r in e) or "(not run)"))
    print(open(os.path.join(OUT, "summary.md")).read())


if __name__ == "__main__":
    main()
