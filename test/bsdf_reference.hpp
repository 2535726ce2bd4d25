// Host-side reference of the scattering models (cl/shading/), in double
// precision and written from their definitions alone, for test/test_bsdf.cpp:
// the microfacet distributions (GGX and Beckmann) and Smith's Lambda,
// dielectric and conductor Fresnel terms, f of every rough model, and
// albedos by deterministic quadrature over the microfacet normals.
//
// Frame: z is the shading normal; wo and wi point away from the surface.
// Indices: a dielectric's outside (z > 0) has index 1, its inside ior.
#pragma once
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

namespace smallmlt::ref {

constexpr double kPi = 3.14159265358979323846;

struct D3 {
    double x = 0, y = 0, z = 0;
};
inline D3 operator+(D3 a, D3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline D3 operator-(D3 a, D3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline D3 operator-(D3 a) {
    return {-a.x, -a.y, -a.z};
}
inline D3 operator*(D3 a, double s) {
    return {a.x * s, a.y * s, a.z * s};
}
inline D3 operator*(double s, D3 a) {
    return a * s;
}
inline double dot(D3 a, D3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline double norm(D3 a) {
    return std::sqrt(dot(a, a));
}
inline D3 unit(D3 a) {
    return a * (1.0 / norm(a));
}
// The unit vector at polar cosine c and azimuth phi about z.
inline D3 polar(double c, double phi) {
    double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    return {s * std::cos(phi), s * std::sin(phi), c};
}
// wo at cosine c to the normal, in the xz-plane (azimuth 0).
inline D3 incident(double c) {
    return {std::sqrt(std::max(0.0, 1.0 - c * c)), 0.0, c};
}

// ---- Microfacet distributions -------------------------------------------

inline double tan2_theta(D3 w) {
    double c2 = w.z * w.z;
    return std::max(0.0, 1.0 - c2) / c2;
}

// D(m) for m.z > 0 (0 below): GGX alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2),
// Beckmann exp(-tan^2 / alpha^2) / (pi alpha^2 cos^4).
inline double ndf(D3 m, double alpha, bool beckmann) {
    if (m.z <= 0) return 0;
    double c4 = m.z * m.z * m.z * m.z, t2 = tan2_theta(m), a2 = alpha * alpha;
    if (beckmann) return std::exp(-t2 / a2) / (kPi * a2 * c4);
    double s = a2 + t2;
    return a2 / (kPi * c4 * s * s);
}

// Smith's Lambda of direction w (either side; it depends on |tan theta|).
// GGX: (sqrt(1 + alpha^2 tan^2) - 1) / 2. Beckmann, with
// a = 1 / (alpha tan): (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)).
inline double smith_lambda(D3 w, double alpha, bool beckmann) {
    double t2 = tan2_theta(w);
    if (t2 <= 0) return 0;
    if (!std::isfinite(t2)) return INFINITY;
    if (!beckmann) {
        double x = alpha * alpha * t2;
        return x / (2.0 * (std::sqrt(1.0 + x) + 1.0)); // (sqrt(1 + x) - 1) / 2, no cancellation
    }
    double a = 1.0 / (alpha * std::sqrt(t2));
    return (std::erf(a) - 1.0) / 2.0 + std::exp(-a * a) / (2.0 * a * std::sqrt(kPi));
}

// G1(w, m): 1 / (1 + Lambda(w)) where w sees the front of m on its own side
// of the surface (dot(w, m) and w.z of one sign), else 0.
inline double smith_g1(D3 w, D3 m, double alpha, bool beckmann) {
    if (dot(w, m) * w.z <= 0) return 0;
    return 1.0 / (1.0 + smith_lambda(w, alpha, beckmann));
}

// The density of visible normals for wo.z > 0:
// G1(wo, m) max(0, dot(wo, m)) D(m) / wo.z.
inline double visible_pdf(D3 wo, D3 m, double alpha, bool beckmann) {
    double c = dot(wo, m);
    if (c <= 0 || m.z <= 0) return 0;
    return smith_g1(wo, m, alpha, beckmann) * c * ndf(m, alpha, beckmann) / wo.z;
}

// ---- Fresnel -------------------------------------------------------------

// Unpolarized reflectance of a smooth dielectric interface for the cosine c
// (>= 0) on the incident side and relative index eta = eta_t / eta_i, in the
// form with g = sqrt(eta^2 - 1 + c^2); g^2 < 0 is total internal reflection.
inline double fresnel(double c, double eta) {
    double g2 = eta * eta - 1.0 + c * c;
    if (g2 <= 0) return 1.0;
    double g = std::sqrt(g2);
    double a = (g - c) / (g + c), b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

// Reflectance of a conductor of complex index n = eta + i k (relative to the
// incident side) at cosine c, from the amplitude coefficients with the
// complex transmitted cosine: n cos_t = sqrt(n^2 - sin^2) on the decaying
// branch (the principal root: its imaginary part is >= 0 when k >= 0).
inline double fresnel_conductor(double c, double eta, double k) {
    std::complex<double> n(eta, k);
    double s2 = std::max(0.0, 1.0 - c * c);
    std::complex<double> nct = std::sqrt(n * n - s2); // n cos_t
    std::complex<double> ct = nct / n;
    std::complex<double> rs = (c - nct) / (c + nct);
    std::complex<double> rp = (n * c - ct) / (n * c + ct);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

// 2 * integral over c in [0, 1] of f(c) c dc, by 4-point Gauss-Legendre on
// equal panels.
template <typename F> double cosine_mean(F f, int panels) {
    static const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                0.8611363115940526};
    static const double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                0.3478548451374538};
    double sum = 0, h = 1.0 / panels;
    for (int p = 0; p < panels; ++p)
        for (int j = 0; j < 4; ++j) {
            double c = (p + 0.5 + 0.5 * x[j]) * h;
            sum += w[j] * 0.5 * h * f(c) * c;
        }
    return 2 * sum;
}

// The cosine-weighted hemispherical reflectance of a smooth interface (the
// kink at the critical angle costs accuracy only in one of many panels).
inline double fresnel_hemispherical(double eta) {
    return cosine_mean([&](double c) { return fresnel(c, eta); }, 4096);
}

// ---- Directions ------------------------------------------------------------

inline D3 reflect(D3 w, D3 m) {
    return 2.0 * dot(w, m) * m - w;
}

// w refracted through a facet of normal m (dot(w, m) > 0) into the side of
// relative index eta = eta_t / eta_i; false on total internal reflection.
inline bool refract(D3 w, D3 m, double eta, D3* out) {
    double c = dot(w, m), s2t = (1.0 - c * c) / (eta * eta);
    if (s2t >= 1.0) return false;
    double ct = std::sqrt(1.0 - s2t);
    *out = (-1.0 / eta) * w + (c / eta - ct) * m;
    return true;
}

// ---- The models' f (RGB channels one at a time) ----------------------------

// Rough conductor (reflection, wo.z, wi.z > 0), with the Fresnel factor fc
// of the channel: fc D(h) G1(wo) G1(wi) / (4 wo.z wi.z).
inline double rough_conductor_f(D3 wo, D3 wi, double fc, double alpha, bool beckmann) {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    D3 h = unit(wo + wi);
    return fc * ndf(h, alpha, beckmann) * smith_g1(wo, h, alpha, beckmann) *
           smith_g1(wi, h, alpha, beckmann) / (4 * wo.z * wi.z);
}

// Rough dielectric of index ior, ks 1, wo and wi on either side. Reflection
// (same side): F(|wo.h|) D G1 G1 / (4 |wo.z| |wi.z|), h = normalize(wo + wi).
// Transmission: with eta_o, eta_i the indices on wo's and wi's sides and the
// generalized half vector h = -(eta_o wo + eta_i wi) (normalized, turned to
// z > 0), |wo.h| |wi.h| eta_o^2 (1 - F) D G1 G1 / (|wo.z| |wi.z|
// (eta_o wo.h + eta_i wi.h)^2): radiance arriving along wi, leaving along wo.
inline double rough_dielectric_f(D3 wo, D3 wi, double ior, double alpha, bool beckmann) {
    if (wo.z == 0 || wi.z == 0) return 0;
    double eo = wo.z > 0 ? 1.0 : ior, ei = wi.z > 0 ? 1.0 : ior;
    double eta = wo.z > 0 ? ior : 1.0 / ior; // the far side's index over wo's
    if (wo.z * wi.z > 0) {
        D3 h = unit(wo + wi);
        if (h.z < 0) h = -h;
        double f = fresnel(std::fabs(dot(wo, h)), eta);
        return f * ndf(h, alpha, beckmann) * smith_g1(wo, h, alpha, beckmann) *
               smith_g1(wi, h, alpha, beckmann) / (4 * std::fabs(wo.z * wi.z));
    }
    D3 h = unit(-(eo * wo + ei * wi));
    if (h.z < 0) h = -h;
    double oh = dot(wo, h), ih = dot(wi, h);
    if (oh * ih >= 0) return 0;
    double f = fresnel(std::fabs(oh), eta), den = eo * oh + ei * ih;
    return std::fabs(oh * ih) * eo * eo * (1 - f) * ndf(h, alpha, beckmann) *
           smith_g1(wo, h, alpha, beckmann) * smith_g1(wi, h, alpha, beckmann) /
           (std::fabs(wo.z * wi.z) * den * den);
}

// ---- Quadrature over microfacet normals ------------------------------------

// The map of the quadratures over microfacet normals: v in [0, 1) to
// tan^2 theta = alpha^2 u / (1 - u) with u = 1 - (1 - v)^2. In u, GGX's
// D(m) m.z is uniform, so the peak is resolved at any alpha (Beckmann's is
// narrower and lighter-tailed than GGX's of the same alpha, so it is
// resolved too); the square root in v takes away the 1 / sqrt(1 - u) that
// the visible normals' factor dot(wo, m) / m.z brings to GGX's tail. Returns
// cos theta and d(solid angle) / (dv dphi).
inline void normal_map(double v, double alpha, double* cos_theta, double* jacobian) {
    double s = 1 - v, u = 1 - s * s, a2 = alpha * alpha;
    double t = a2 * u / (s * s), dt_du = a2 / (s * s * s * s), du_dv = 2 * s;
    double c = 1.0 / std::sqrt(1 + t);
    *cos_theta = c;
    *jacobian = 0.5 * c * c * c * dt_du * du_dv; // d(-cos) = (1 + t)^(-3/2) dt / 2
}

// The expectation of g(m) over the visible normals of wo (wo.z > 0):
// integral of g(m) G1(wo) max(0, wo.m) D(m) / wo.z dm, by the midpoint rule
// in (v, phi) of normal_map. wo lies in the xz-plane, so phi runs over
// [0, pi] and counts twice.
template <typename G>
double visible_expectation(D3 wo, double alpha, bool beckmann, G g, int nv = 1024, int nphi = 256) {
    double g1o = 1.0 / (1.0 + smith_lambda(wo, alpha, beckmann));
    double du = 1.0 / nv, dphi = kPi / nphi, sum = 0;
    for (int i = 0; i < nv; ++i) {
        double c, jac;
        normal_map((i + 0.5) * du, alpha, &c, &jac);
        for (int j = 0; j < nphi; ++j) {
            D3 m = polar(c, (j + 0.5) * dphi);
            double om = dot(wo, m);
            if (om <= 0) continue;
            double p = g1o * om * ndf(m, alpha, beckmann) / wo.z;
            sum += p * jac * g(m);
        }
    }
    return 2 * sum * du * dphi;
}

// Single-scattering albedo of the rough conductor with Fresnel factor 1:
// the visible normals' expectation of G1(wi) for wi the reflection of wo.
inline double rough_conductor_albedo(D3 wo, double alpha, bool beckmann) {
    return visible_expectation(wo, alpha, beckmann, [&](D3 m) {
        D3 wi = reflect(wo, m);
        return wi.z > 0 ? smith_g1(wi, m, alpha, beckmann) : 0.0;
    });
}

// Albedo of the rough dielectric (ks 1) seen along wo (either side), with the
// transmitted part's radiance scaling (eta_o / eta_i)^2 undone: the visible
// normals' expectation of F G1(reflected) + (1 - F) G1(refracted). A
// direction on the wrong side of the surface counts 0.
inline double rough_dielectric_albedo(D3 wo, double ior, double alpha, bool beckmann) {
    bool inside = wo.z < 0;
    D3 w = inside ? D3{wo.x, wo.y, -wo.z} : wo; // the same geometry seen from +z
    double eta = inside ? 1.0 / ior : ior;      // eta_t / eta_i
    return visible_expectation(w, alpha, beckmann, [&](D3 m) {
        double f = fresnel(dot(w, m), eta), r = 0;
        D3 wr = reflect(w, m), wt;
        if (wr.z > 0) r += f * smith_g1(wr, m, alpha, beckmann);
        if (f < 1 && refract(w, m, eta, &wt) && wt.z < 0)
            r += (1 - f) * smith_g1(wt, m, alpha, beckmann);
        return r;
    });
}

// ---- Plastic's coat ----------------------------------------------------------

// A rough dielectric interface of index ior at cosine c. Seen from outside
// (inside false): the energy it refracts inside, the visible normals'
// expectation of (1 - F(wo.m)) G1(refracted). Seen from inside: the energy
// it reflects back, the expectation of F(wo.m, 1 / ior) G1(reflected).
inline double coat_energy(bool inside, double c, double ior, double alpha, bool beckmann, int nv,
                          int nphi) {
    D3 wo = incident(c);
    double eta = inside ? 1 / ior : ior;
    auto g = [&](D3 m) {
        double f = fresnel(dot(wo, m), eta);
        D3 w = reflect(wo, m);
        if (inside) return w.z > 0 ? f * smith_g1(w, m, alpha, beckmann) : 0.0;
        if (!refract(wo, m, eta, &w) || w.z >= 0) return 0.0;
        return (1 - f) * smith_g1(w, m, alpha, beckmann);
    };
    return visible_expectation(wo, alpha, beckmann, g, nv, nphi);
}

// Plastic's coat as the model uses it. Smooth: t = 1 - F, inner the
// hemispherical reflectance from inside. Rough: t at cos = i / (nodes - 1)
// (1e-6 for i = 0) joined linearly, inner = 2 * integral of the reflectance
// inside times cos.
struct Coat {
    bool rough = false;
    double ior = 1.5;
    std::vector<double> t;
    double inner = 0;

    double transmittance(double c) const {
        if (!rough) return 1 - fresnel(c, ior);
        double x = std::clamp(c, 0.0, 1.0) * double(t.size() - 1);
        std::size_t i = std::min(std::size_t(x), t.size() - 2);
        return t[i] + (x - double(i)) * (t[i + 1] - t[i]);
    }
};

inline Coat smooth_coat(double ior) {
    Coat c;
    c.ior = ior;
    c.inner = fresnel_hemispherical(1 / ior);
    return c;
}

inline Coat rough_coat(double ior, double alpha, bool beckmann, int nodes, int nv = 512,
                       int nphi = 128) {
    Coat c;
    c.rough = true;
    c.ior = ior;
    for (int i = 0; i < nodes; ++i)
        c.t.push_back(coat_energy(false, std::max(1e-6, double(i) / (nodes - 1)), ior, alpha,
                                  beckmann, nv, nphi));
    c.inner = cosine_mean(
        [&](double x) { return coat_energy(true, x, ior, alpha, beckmann, nv, nphi); }, 16);
    return c;
}

// Plastic, one channel: the coat's microfacet lobe (rough only) plus the base
// kd / pi t(wo.z) t(wi.z) / (ior^2 (1 - inner)).
inline double plastic_f(D3 wo, D3 wi, double kd, double ks, double ior, const Coat& coat,
                        double alpha, bool beckmann, bool rough) {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    double base = kd / kPi * coat.transmittance(wo.z) * coat.transmittance(wi.z) /
                  (ior * ior * (1 - coat.inner));
    if (!rough) return base;
    D3 h = unit(wo + wi);
    double lobe = ks * fresnel(dot(wo, h), ior) * ndf(h, alpha, beckmann) *
                  smith_g1(wo, h, alpha, beckmann) * smith_g1(wi, h, alpha, beckmann) /
                  (4 * wo.z * wi.z);
    return lobe + base;
}

// Albedo of the rough plastic, one channel (wo.z > 0): the coat's expectation
// of ks F(wo.m) G1(wi) plus the base kd t(wo.z) T / (ior^2 (1 - inner)), T
// the cosine-weighted mean of t.
inline double rough_plastic_albedo(D3 wo, double kd, double ks, double ior, const Coat& coat,
                                   double alpha, bool beckmann) {
    double lobe = visible_expectation(wo, alpha, beckmann, [&](D3 m) {
        D3 wi = reflect(wo, m);
        return wi.z > 0 ? fresnel(dot(wo, m), ior) * smith_g1(wi, m, alpha, beckmann) : 0.0;
    });
    double t_mean = cosine_mean([&](double c) { return coat.transmittance(c); }, 1024);
    double base = kd * coat.transmittance(wo.z) * t_mean / (ior * ior * (1 - coat.inner));
    return ks * lobe + base;
}

} // namespace smallmlt::ref
