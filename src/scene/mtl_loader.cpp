// Reader of MTL material files: the subset of doc/scene-format.md, and an
// error naming file and line for anything else.
#include "base/error.hpp"
#include "scene/material.hpp"
#include "scene/scene.hpp"
#include "scene/text_parse.hpp"

namespace smallmlt {

namespace {

struct PendingMaterial {
    std::string name;
    int line = 0;
    float kd[3] = {0, 0, 0}, ke[3] = {0, 0, 0}, ks[3] = {0, 0, 0};
    float ior = 0;
    int illum = 1, illum_line = 0;
    bool has_ks = false;
};

void read_rgb(const std::vector<std::string>& t, const std::string& file, int line, float lo,
              float hi, float out[3]) {
    if (t.size() != 4) throw input_error(file, line, "'" + t[0] + "' takes three numbers (R G B)");
    for (int i = 0; i < 3; ++i) {
        out[i] = parse_float(t[1 + i], file, line, t[0].c_str());
        if (out[i] < lo || out[i] > hi)
            throw input_error(file, line,
                              "'" + t[0] + "' values must be in [" + std::to_string(lo) + ", " +
                                  (hi > 1e30f ? std::string("inf") : std::to_string(hi)) + "]");
    }
}

Vec3 vec(const float c[3]) {
    return {c[0], c[1], c[2]};
}

Material finish(const PendingMaterial& p, const std::string& file) {
    Material m{};
    switch (p.illum) {
    case 0:
    case 1:
        m = diffuse_material(vec(p.kd));
        break;
    case 2:
        if (p.ks[0] > 0 || p.ks[1] > 0 || p.ks[2] > 0)
            throw input_error(file, p.illum_line,
                              "material '" + p.name +
                                  "': illum 2 with non-zero Ks is a glossy highlight, which is "
                                  "not supported (use Ks 0 0 0, or illum 5 for a mirror)");
        m = diffuse_material(vec(p.kd));
        break;
    case 3:
    case 5:
        if (!p.has_ks)
            throw input_error(file, p.illum_line,
                              "material '" + p.name + "': a mirror (illum " +
                                  std::to_string(p.illum) + ") needs Ks");
        m = conductor_material(vec(p.ks), {0, 0, 0}, {1, 1, 1}, 0.0f);
        break;
    case 7:
        if (!(p.ior > 0))
            throw input_error(file, p.illum_line,
                              "material '" + p.name + "': a dielectric (illum 7) needs Ni > 0");
        m = dielectric_material(p.ior, 0.0f);
        break;
    default:
        throw input_error(file, p.illum_line,
                          "material '" + p.name + "': illum " + std::to_string(p.illum) +
                              " is not supported (0, 1, 2: diffuse; 3, 5: mirror; 7: dielectric)");
    }
    set_emission(m, vec(p.ke));
    return m;
}

void add_material(Scene& scene, const PendingMaterial& p, const std::string& file) {
    for (const std::string& n : scene.material_names)
        if (n == p.name)
            throw input_error(file, p.line, "material '" + p.name + "' is defined twice");
    scene.materials.push_back(finish(p, file));
    scene.material_names.push_back(p.name);
}

} // namespace

void load_mtl(const std::string& path, Scene& scene) {
    PendingMaterial cur;
    bool open = false;
    for_each_directive(path, "material", [&](int line, const std::vector<std::string>& t) {
        const std::string& d = t[0];
        if (d == "newmtl") {
            if (t.size() != 2) throw input_error(path, line, "'newmtl' takes one name");
            if (open) add_material(scene, cur, path);
            cur = PendingMaterial();
            cur.name = t[1];
            cur.line = cur.illum_line = line;
            open = true;
            return;
        }
        if (!open) throw input_error(path, line, "'" + d + "' before any 'newmtl'");
        if (d == "Kd") {
            read_rgb(t, path, line, 0.0f, 1.0f, cur.kd);
        } else if (d == "Ks") {
            read_rgb(t, path, line, 0.0f, 1.0f, cur.ks);
            cur.has_ks = true;
        } else if (d == "Ke") {
            read_rgb(t, path, line, 0.0f, 3.0e38f, cur.ke);
        } else if (d == "Ni") {
            if (t.size() != 2) throw input_error(path, line, "'Ni' takes one number");
            cur.ior = parse_float(t[1], path, line, "Ni");
            if (!(cur.ior > 0)) throw input_error(path, line, "'Ni' must be > 0");
        } else if (d == "illum") {
            if (t.size() != 2) throw input_error(path, line, "'illum' takes one integer");
            cur.illum = static_cast<int>(parse_int(t[1], path, line, "illum"));
            cur.illum_line = line;
        } else if (d == "Ka" || d == "Ns") {
            // Ambient colour and Phong exponent: no meaning for the supported
            // materials; read for their syntax and ignored (documented).
            if (t.size() < 2) throw input_error(path, line, "'" + d + "' takes a value");
            for (std::size_t i = 1; i < t.size(); ++i)
                parse_float(t[i], path, line, d.c_str());
        } else if (d == "d" || d == "Tr") {
            if (t.size() != 2) throw input_error(path, line, "'" + d + "' takes one number");
            float v = parse_float(t[1], path, line, d.c_str());
            if (v != (d == "d" ? 1.0f : 0.0f))
                throw input_error(path, line,
                                  "partial transparency ('" + d +
                                      "') is not supported; use illum 7 for glass");
        } else {
            throw input_error(path, line, "unsupported material directive '" + d + "'");
        }
    });
    if (open) add_material(scene, cur, path);
}

} // namespace smallmlt
