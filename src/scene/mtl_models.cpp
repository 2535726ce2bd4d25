// From what an MTL material says to a Material: illum picks the model, Pm
// can make it a metal, Pr or Ns its roughness (doc/scene-format.md, MTL).
#include "scene/mtl_models.hpp"

#include "base/error.hpp"
#include "scene/material.hpp"

#include <algorithm>
#include <cmath>

namespace smallmlt {

namespace {

// The models an MTL material can become, as far as what they read.
enum class Kind {
    Diffuse,    // Kd
    Plastic,    // Kd, Ks, Ni, roughness
    Mirror,     // Ks, roughness (a conductor of Fresnel term 1)
    Metal,      // Kd as the mirror's colour (Pm), roughness
    Dielectric, // Ni, roughness
};

bool is_dielectric_illum(long illum) {
    return illum == 4 || illum == 6 || illum == 7 || illum == 9;
}

bool is_mirror_illum(long illum) {
    return illum == 3 || illum == 5 || illum == 8;
}

bool nonzero(Vec3 c) {
    return c.x != 0 || c.y != 0 || c.z != 0;
}

Kind kind_of(const MtlMaterial& m) {
    if (is_dielectric_illum(m.illum)) return Kind::Dielectric;
    if (m.pm >= kMetalPm) return Kind::Metal;
    if (is_mirror_illum(m.illum)) return Kind::Mirror;
    if (m.illum == 2 && nonzero(m.ks)) return Kind::Plastic;
    return Kind::Diffuse; // 0, 1, 10, and 2 without a highlight
}

bool is_one_of(const std::string& d, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (d == n) return true;
    return false;
}

// Whether line `l` of `m` changes nothing in the model `k` it became.
bool changes_nothing(const MtlLine& l, Kind k, const MtlMaterial& m) {
    const std::string& d = l.directive;
    // Ambient light, transmission filters, surface detail and features that
    // no model here has.
    if (is_one_of(d, {"Ka", "map_Ka", "Tf", "sharpness", "map_Bump", "map_bump", "bump", "norm",
                      "disp", "decal", "refl", "map_refl", "map_Ps", "map_Pc", "map_Pcr"}))
        return true;
    // Clearcoat, sheen and anisotropy: only where they are not zero; their
    // roughness and rotation only where the feature itself is there.
    if (is_one_of(d, {"Pc", "Ps", "aniso"})) return l.nonzero;
    if (d == "Pcr") return m.pc != 0;
    if (d == "anisor") return m.aniso != 0;
    bool diffuse = k == Kind::Diffuse;
    if (d == "Ni") return diffuse || k == Kind::Mirror || k == Kind::Metal;
    if (d == "Ns") return diffuse || m.pr.has_value();
    if (d == "Pr") return diffuse;
    if (d == "Ks") return l.nonzero && (diffuse || k == Kind::Dielectric || k == Kind::Metal);
    if (d == "Kd") return l.nonzero && (k == Kind::Mirror || k == Kind::Dielectric);
    if (d == "Pm") return l.nonzero && k == Kind::Dielectric;
    return false;
}

} // namespace

float roughness_from_ns(float ns) {
    return std::clamp(1.0f - std::sqrt(ns / kMaxNs), 0.0f, 1.0f);
}

float mtl_roughness(const MtlMaterial& m) {
    if (m.pr) return *m.pr;
    if (m.ns) return roughness_from_ns(*m.ns);
    return 0.0f;
}

MtlMapping map_mtl_material(const MtlMaterial& m, const std::string& file) {
    std::string illum = "illum " + std::to_string(m.illum);
    auto fail = [&](const std::string& why) {
        return input_error(file, m.illum_line, "material '" + m.name + "': " + why);
    };
    if (m.illum < 0 || m.illum > 10)
        throw fail(illum + " is not supported (0-10: 0, 1 diffuse; 2 plastic, or diffuse "
                           "without Ks; 3, 5, 8 mirror; 4, 6, 7, 9 dielectric; 10 as 1)");
    float r = mtl_roughness(m);
    float alpha = r * r;
    // A roughness map makes the model rough, whatever the constant says.
    if (m.map_pr && !(alpha >= kSmoothAlpha)) alpha = kSmoothAlpha;
    Kind kind = kind_of(m);
    MtlMapping out;
    switch (kind) {
    case Kind::Diffuse:
        out.material = diffuse_material(m.kd);
        break;
    case Kind::Plastic:
        out.material = plastic_material(m.kd, m.ks, m.ni.value_or(1.5f), alpha);
        break;
    case Kind::Mirror:
        if (!m.has_ks) throw fail("a mirror (" + illum + ") needs Ks");
        out.material = conductor_material(m.ks, {0, 0, 0}, {1, 1, 1}, alpha);
        break;
    case Kind::Metal:
        out.material = conductor_material(m.kd, {0, 0, 0}, {1, 1, 1}, alpha);
        break;
    case Kind::Dielectric:
        if (!m.ni) throw fail("a dielectric (" + illum + ") needs Ni > 0");
        out.material = dielectric_material(*m.ni, alpha);
        break;
    }
    set_emission(out.material, m.ke);
    for (const MtlLine& l : m.lines)
        if (changes_nothing(l, kind, m)) out.ignored.push_back(l);
    // The maps the model reads; the others change nothing.
    bool base = kind == Kind::Diffuse || kind == Kind::Plastic;
    if (m.map_kd && (base || kind == Kind::Metal))
        out.textures.push_back({base ? &Material::kd_tex : &Material::ks_tex, *m.map_kd,
                                TextureKind::Colour, &MtlMaterial::kd});
    else if (m.map_kd)
        out.ignored.push_back({"map_Kd", m.map_kd->line, true});
    if (m.map_ks && (kind == Kind::Plastic || kind == Kind::Mirror))
        out.textures.push_back(
            {&Material::ks_tex, *m.map_ks, TextureKind::Colour, &MtlMaterial::ks});
    else if (m.map_ks)
        out.ignored.push_back({"map_Ks", m.map_ks->line, true});
    if (m.map_pr && kind != Kind::Diffuse)
        out.textures.push_back({&Material::rough_tex, *m.map_pr, TextureKind::Data, nullptr});
    else if (m.map_pr)
        out.ignored.push_back({"map_Pr", m.map_pr->line, true});
    // Emitters and dielectrics are not cut out.
    if (m.map_d && kind != Kind::Dielectric && !out.material.emissive)
        out.textures.push_back({&Material::alpha_tex, *m.map_d, TextureKind::Mask, nullptr});
    else if (m.map_d)
        out.ignored.push_back({"map_d", m.map_d->line, true});
    return out;
}

} // namespace smallmlt
