#include "scene/material.hpp"

#include "base/color.hpp"
#include "scene/plastic_coat.hpp"

namespace smallmlt {

namespace {

Material base(u32 type) {
    Material m{};
    m.type = type;
    m.ior = 1.0f;
    m.flags = MAT_FLAG_TWO_SIDED;
    m.kd_tex = m.ks_tex = m.rough_tex = m.alpha_tex = TEX_NONE;
    return m;
}

u32 distribution_flag(Microfacet d) {
    return d == Microfacet::Beckmann ? MAT_FLAG_BECKMANN : 0u;
}

} // namespace

Material diffuse_material(Vec3 kd) {
    Material m = base(MAT_DIFFUSE);
    store3(m.kd, kd);
    return m;
}

Material conductor_material(Vec3 ks, Vec3 eta, Vec3 k, float alpha, Microfacet d) {
    bool rough = alpha >= kSmoothAlpha;
    Material m = base(rough ? MAT_ROUGH_CONDUCTOR : MAT_CONDUCTOR);
    store3(m.ks, ks);
    store3(m.eta, eta);
    store3(m.k, k);
    m.alpha = rough ? alpha : 0.0f;
    m.flags |= distribution_flag(d);
    return m;
}

Material dielectric_material(float ior, float alpha, Microfacet d) {
    bool rough = alpha >= kSmoothAlpha;
    Material m = base(rough ? MAT_ROUGH_DIELECTRIC : MAT_DIELECTRIC);
    store3(m.ks, {1, 1, 1});
    m.ior = ior;
    m.alpha = rough ? alpha : 0.0f;
    m.flags = distribution_flag(d); // both sides are its own
    return m;
}

Material thin_dielectric_material(float ior) {
    Material m = base(MAT_THIN_DIELECTRIC);
    store3(m.ks, {1, 1, 1});
    m.ior = ior;
    m.flags = 0; // both sides are its own
    return m;
}

Material plastic_material(Vec3 kd, Vec3 ks, float ior, float alpha, Microfacet d) {
    bool rough = alpha >= kSmoothAlpha;
    Material m = base(rough ? MAT_ROUGH_PLASTIC : MAT_PLASTIC);
    store3(m.kd, kd);
    store3(m.ks, ks);
    m.ior = ior;
    m.alpha = rough ? alpha : 0.0f;
    m.flags |= distribution_flag(d);
    if (rough) {
        RoughCoat coat = integrate_rough_coat(ior, m.alpha, d == Microfacet::Beckmann);
        store_coat_transmittance(m, coat);
        m.fdr_int = static_cast<f32>(coat.inner_reflectance);
    } else {
        m.fdr_int = static_cast<f32>(fresnel_diffuse_reflectance(1.0 / ior));
    }
    double s = rgb_luminance(ks.x, ks.y, ks.z), b = rgb_luminance(kd.x, kd.y, kd.z);
    m.spec_weight = s + b > 0 ? static_cast<f32>(s / (s + b)) : 0.5f;
    return m;
}

void set_emission(Material& m, Vec3 ke) {
    store3(m.ke, ke);
    m.emissive = (ke.x > 0 || ke.y > 0 || ke.z > 0) ? 1u : 0u;
}

} // namespace smallmlt
