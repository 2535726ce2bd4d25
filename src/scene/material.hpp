// Constructors of the shared Material (cl/core/shared_types.h): each sets
// the fields its model reads and the ones derived from them, so a Material
// made here is complete. Definitions of the models: doc/design.md,
// "Materials".
#pragma once
#include "base/vec3.hpp"
#include "shared_types.h"

namespace smallmlt {

// A microfacet alpha below this is read as a smooth surface: the smooth
// model renders it (its lobe is narrower than one pixel's blur at any
// distance the scenes use, and a GGX lobe that narrow loses float precision).
constexpr float kSmoothAlpha = MAT_MIN_ROUGH_ALPHA;

enum class Microfacet { Ggx, Beckmann };

Material diffuse_material(Vec3 kd);
// A conductor of complex index eta + i k; ks scales its Fresnel term.
// eta 0, k 1 reflects everything (a mirror of reflectance ks).
Material conductor_material(Vec3 ks, Vec3 eta, Vec3 k, float alpha, Microfacet d = Microfacet::Ggx);
Material dielectric_material(float ior, float alpha, Microfacet d = Microfacet::Ggx);
// A thin sheet of index ior: reflects 2F / (1 + F), passes the rest straight.
Material thin_dielectric_material(float ior);
// A diffuse base of albedo kd under a dielectric coat of index ior.
Material plastic_material(Vec3 kd, Vec3 ks, float ior, float alpha, Microfacet d = Microfacet::Ggx);

void set_emission(Material& m, Vec3 ke);

} // namespace smallmlt
