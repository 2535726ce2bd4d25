// The dielectric coat of plastic, integrated once per material on the host:
// the smooth interface's Fresnel term and hemispherical reflectance, and the
// rough coat of MAT_ROUGH_PLASTIC. The base under a rough coat (the model of
// Mitsuba 3's roughplastic) sees light through the coat's transmittance t(cos), the
// energy that a rough dielectric interface of Smith microfacets refracts
// from a direction at that cosine, and is lit again by the coat's inner
// reflectance: 2 * integral over cos in [0, 1] of the interface's
// single-scattering reflectance from inside times cos. A smooth coat has
// t = 1 - F and the inner reflectance of fresnel_diffuse_reflectance.
#pragma once
#include "shared_types.h"

#include <array>

namespace smallmlt {

// Unpolarized Fresnel reflectance of a smooth interface for cosine cos_i on
// the incident side and relative index eta = eta_t / eta_i (total internal
// reflection gives 1).
double fresnel_dielectric(double cos_i, double eta);

// The cosine-weighted hemispherical average of fresnel_dielectric:
// 2 * integral over cos in [0, 1] of F(cos, eta) cos, by Simpson's rule.
double fresnel_diffuse_reflectance(double eta);

struct RoughCoat {
    std::array<double, COAT_T_SIZE> transmittance; // at cos = i / (COAT_T_SIZE - 1)
    double inner_reflectance;
};

// The coat of index ior (outside 1) and roughness alpha.
RoughCoat integrate_rough_coat(double ior, double alpha, bool beckmann);

// Material.coat_t from coat.transmittance (16-bit fixed point, rounded).
void store_coat_transmittance(Material& m, const RoughCoat& coat);

} // namespace smallmlt
