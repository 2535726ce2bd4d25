#include "scene/mitsuba_bsdfs.hpp"

#include "base/error.hpp"
#include "scene/material.hpp"
#include "scene/mitsuba_textures.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace smallmlt {

namespace {

struct NamedIor {
    const char* name;
    double ior;
};

// Mitsuba's table of indices of refraction (Mitsuba 3, ior.h).
const NamedIor kIors[] = {
    {"vacuum", 1.0},      {"helium", 1.000036},        {"hydrogen", 1.000132},
    {"air", 1.000277},    {"carbon dioxide", 1.00045}, {"water", 1.3330},
    {"acetone", 1.36},    {"ethanol", 1.361},          {"carbon tetrachloride", 1.461},
    {"glycerol", 1.4729}, {"benzene", 1.501},          {"silicone oil", 1.52045},
    {"bromine", 1.661},   {"water ice", 1.31},         {"fused quartz", 1.458},
    {"pyrex", 1.470},     {"acrylic glass", 1.49},     {"polypropylene", 1.49},
    {"bk7", 1.5046},      {"sodium chloride", 1.544},  {"amber", 1.55},
    {"pet", 1.5750},      {"diamond", 2.419},
};

void fail(const XmlObject& o, const std::string& msg) {
    throw input_error(o.where.file, o.where.line, o.tag + " '" + o.type + "': " + msg);
}

// An index of refraction given as a <float> or as a name of the table.
double ior_of(const XmlObject& o, const std::string& name, double fallback) {
    const XmlProperty* p = o.find(name);
    if (!p) return fallback;
    if (p->tag == "string") {
        double v = mitsuba_named_ior(xml_string(o, name, ""));
        if (v < 0)
            throw input_error(p->where.file, p->where.line,
                              "'" + p->text +
                                  "' is not in Mitsuba's table of indices of "
                                  "refraction (bk7, water, air, diamond, ...)");
        return v;
    }
    double v = xml_float(o, name, fallback);
    if (!(v > 0))
        throw input_error(p->where.file, p->where.line, "'" + name + "' must be positive");
    return v;
}

// A colour parameter that cannot be a texture: a constant (rgb, uniform
// spectrum or float).
Vec3 color_of(const XmlObject& o, const std::string& name, Vec3 fallback) {
    for (const XmlObject* c : o.children)
        if (c->tag == "texture" && c->name == name)
            throw input_error(c->where.file, c->where.line,
                              "texture '" + c->type + "' as '" + name +
                                  "' is not read (textures are read as reflectances: "
                                  "reflectance, diffuse_reflectance, specular_reflectance)");
    return xml_color(o, name, fallback);
}

// A colour parameter that may be a texture: its constant, or the texture's
// index in *tex (appended to scene.textures) and its mean colour.
Vec3 texturable(const XmlObject& o, const std::string& name, Vec3 fallback, Scene& scene,
                u32* tex) {
    for (const XmlObject* c : o.children)
        if (c->tag == "texture" && c->name == name) {
            if (o.find(name)) fail(o, "'" + name + "' is given twice");
            Vec3 mean;
            *tex = add_mitsuba_texture(*c, scene, &mean);
            return mean;
        }
    return xml_color(o, name, fallback);
}

Microfacet distribution_of(const XmlObject& o) {
    std::string d = xml_string(o, "distribution", "beckmann");
    std::transform(d.begin(), d.end(), d.begin(), [](unsigned char c) { return std::tolower(c); });
    if (d == "beckmann") return Microfacet::Beckmann;
    if (d == "ggx") return Microfacet::Ggx;
    fail(o, "distribution '" + d + "' is not read (beckmann, ggx)");
    return Microfacet::Ggx;
}

// alpha, or alpha_u and alpha_v where they are equal (default 0.1).
float alpha_of(const XmlObject& o) {
    const bool has_uv = o.find("alpha_u") || o.find("alpha_v");
    if (has_uv && o.find("alpha")) fail(o, "give 'alpha' or 'alpha_u' and 'alpha_v', not both");
    double a = xml_float(o, "alpha", 0.1);
    if (has_uv) {
        double u = xml_float(o, "alpha_u", -1), v = xml_float(o, "alpha_v", -1);
        if (u != v) fail(o, "anisotropic roughness (alpha_u != alpha_v) is not read");
        a = u;
    }
    if (!(a >= 0)) fail(o, "alpha must be at least 0");
    // Mitsuba samples visible normals or not; the image is the same.
    xml_bool(o, "sample_visible", true);
    return float(a); // below kSmoothAlpha: the smooth model
}

// specular_reflectance / specular_transmittance where the model has no such
// factor: read, and a warning unless 1.
void unit_factor(const XmlObject& o, const std::string& name, std::vector<std::string>& warnings) {
    const XmlProperty* p = o.find(name);
    Vec3 v = color_of(o, name, {1, 1, 1});
    if (p && (v.x != 1 || v.y != 1 || v.z != 1))
        warnings.push_back(p->where.str() + ": warning: '" + name + "' of " + o.tag + " '" +
                           o.type + "' is read as 1 (the dielectric has no such factor)");
}

Material conductor(const XmlObject& o, bool rough, Scene& scene) {
    Vec3 eta{0, 0, 0}, k{1, 1, 1};
    const bool named = o.find("material") != nullptr;
    if (named && (o.find("eta") || o.find("k")))
        fail(o, "give 'material' or 'eta' and 'k', not both");
    if (named) {
        std::string m = xml_string(o, "material", "none");
        if (!mitsuba_named_conductor(m, eta, k))
            fail(o, "material '" + m +
                        "' is not in Mitsuba's table of conductors (Cu, Au, Ag, Al, ...)");
    } else {
        eta = color_of(o, "eta", {0, 0, 0});
        k = color_of(o, "k", {1, 1, 1});
    }
    u32 ks_tex = TEX_NONE;
    Vec3 ks = texturable(o, "specular_reflectance", {1, 1, 1}, scene, &ks_tex);
    Microfacet d = rough ? distribution_of(o) : Microfacet::Ggx;
    float alpha = rough ? alpha_of(o) : 0.0f;
    Material m = conductor_material(ks, eta, k, alpha, d);
    m.ks_tex = ks_tex;
    return m;
}

// A dielectric's relative index int_ior / ext_ior (bk7 in air by default);
// its specular factors, which smallmlt's dielectrics lack, are read as 1.
double dielectric_eta(const XmlObject& o, std::vector<std::string>& warnings) {
    unit_factor(o, "specular_reflectance", warnings);
    unit_factor(o, "specular_transmittance", warnings);
    return ior_of(o, "int_ior", 1.5046) / ior_of(o, "ext_ior", 1.000277);
}

Material dielectric(const XmlObject& o, bool rough, std::vector<std::string>& warnings) {
    double eta = dielectric_eta(o, warnings);
    if (!rough) return dielectric_material(float(eta), 0.0f);
    if (eta == 1) fail(o, "int_ior and ext_ior must differ");
    Microfacet d = distribution_of(o);
    return dielectric_material(float(eta), alpha_of(o), d);
}

Material thin_dielectric(const XmlObject& o, std::vector<std::string>& warnings) {
    return thin_dielectric_material(float(dielectric_eta(o, warnings)));
}

Material plastic(const XmlObject& o, bool rough, Scene& scene) {
    std::vector<std::string>& warnings = scene.warnings;
    u32 kd_tex = TEX_NONE, ks_tex = TEX_NONE;
    Vec3 kd = texturable(o, "diffuse_reflectance", {0.5f, 0.5f, 0.5f}, scene, &kd_tex);
    Vec3 ks = texturable(o, "specular_reflectance", {1, 1, 1}, scene, &ks_tex);
    double eta = ior_of(o, "int_ior", 1.49) / ior_of(o, "ext_ior", 1.000277);
    if (!(eta > 1)) fail(o, "int_ior must exceed ext_ior");
    const XmlProperty* nl = o.find("nonlinear");
    if (xml_bool(o, "nonlinear", false))
        warnings.push_back(nl->where.str() + ": warning: 'nonlinear' of " + o.tag + " '" + o.type +
                           "' is read as false (the linear sum of inner reflections)");
    if (rough && (o.find("alpha_u") || o.find("alpha_v")))
        fail(o, "anisotropic roughness is not read");
    Material m;
    if (rough) {
        Microfacet d = distribution_of(o);
        m = plastic_material(kd, ks, float(eta), alpha_of(o), d);
    } else {
        m = plastic_material(kd, ks, float(eta), 0.0f);
    }
    m.kd_tex = kd_tex;
    m.ks_tex = ks_tex;
    return m;
}

} // namespace

double mitsuba_named_ior(const std::string& name) {
    std::string n = name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
    for (const NamedIor& i : kIors)
        if (n == i.name) return i.ior;
    return -1;
}

Material mitsuba_default_material(bool emitter) {
    float r = emitter ? 0.0f : 0.5f;
    Material m = diffuse_material({r, r, r});
    m.flags &= ~MAT_FLAG_TWO_SIDED;
    return m;
}

Material mitsuba_material(const XmlObject& o, Scene& scene) {
    std::vector<std::string>& warnings = scene.warnings;
    Material m{};
    bool two_sided = false;
    const XmlObject* b = &o;
    if (o.type == "twosided") {
        std::vector<const XmlObject*> inner;
        for (const XmlObject* c : o.children)
            if (c->tag == "bsdf") inner.push_back(c);
        if (inner.size() != 1)
            fail(o, inner.empty() ? "needs a nested bsdf"
                                  : "with a different bsdf on each side is not read");
        b = inner[0];
        two_sided = true;
        xml_warn_unread(o, warnings);
    }
    const std::string& t = b->type;
    if (t == "diffuse") {
        u32 kd_tex = TEX_NONE;
        m = diffuse_material(texturable(*b, "reflectance", {0.5f, 0.5f, 0.5f}, scene, &kd_tex));
        m.kd_tex = kd_tex;
    } else if (t == "conductor" || t == "roughconductor") {
        m = conductor(*b, t == "roughconductor", scene);
    } else if (t == "dielectric" || t == "roughdielectric") {
        if (two_sided) fail(o, "a dielectric inside twosided is not read (it transmits)");
        m = dielectric(*b, t == "roughdielectric", warnings);
    } else if (t == "thindielectric") {
        if (two_sided) fail(o, "a dielectric inside twosided is not read (it transmits)");
        m = thin_dielectric(*b, warnings);
    } else if (t == "plastic" || t == "roughplastic") {
        m = plastic(*b, t == "roughplastic", scene);
    } else if (t == "twosided") {
        fail(*b, "twosided inside twosided");
    } else {
        fail(*b, "is not read (diffuse, twosided, conductor, roughconductor, dielectric, "
                 "roughdielectric, thindielectric, plastic and roughplastic are)");
    }
    if (t != "dielectric" && t != "roughdielectric" && t != "thindielectric") {
        if (two_sided)
            m.flags |= MAT_FLAG_TWO_SIDED;
        else
            m.flags &= ~MAT_FLAG_TWO_SIDED;
    }
    // A texture under any other name is refused by color_of.
    const bool diffuse = t == "diffuse", coated = t == "plastic" || t == "roughplastic",
               metal = t == "conductor" || t == "roughconductor";
    for (const XmlObject* c : b->children)
        if (c->tag == "texture" && !(diffuse && c->name == "reflectance") &&
            !(coated && c->name == "diffuse_reflectance") &&
            !((coated || metal) && c->name == "specular_reflectance"))
            color_of(*b, c->name, {});
    xml_warn_unread(*b, warnings);
    return m;
}

} // namespace smallmlt
