#include "scene/plastic_coat.hpp"

#include <algorithm>
#include <cmath>

namespace smallmlt {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Dir {
    double x, y, z;
};

double dot(Dir a, Dir b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// Smith's G1 of direction w for the facet m: 0 where w sees m's back.
// Lambda: GGX (sqrt(1 + alpha^2 tan^2) - 1) / 2; Beckmann, with
// a = 1 / (alpha tan), (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)).
double smith_g1(Dir w, Dir m, double alpha, bool beckmann) {
    if (dot(w, m) * w.z <= 0) return 0;
    double tan2 = std::max(0.0, 1 - w.z * w.z) / (w.z * w.z);
    if (tan2 == 0) return 1;
    double lambda;
    if (beckmann) {
        double a = 1 / (alpha * std::sqrt(tan2));
        lambda = 0.5 * (std::erf(a) - 1) + std::exp(-a * a) / (2 * a * std::sqrt(kPi));
    } else {
        double x = alpha * alpha * tan2;
        lambda = x / (2 * (std::sqrt(1 + x) + 1));
    }
    return 1 / (1 + lambda);
}

// The mean over the microfacet normals visible from w = (sin, 0, cos) of
// g(m): integral of g(m) G1(w, m) max(0, w.m) D(m) / w.z over m. The normals
// are drawn by inverting the distribution's CDF in u (D(m) m.z dm =
// du dphi / 2 pi: tan^2 = alpha^2 u / (1 - u) for GGX, -alpha^2 ln(1 - u) for
// Beckmann) with u = 1 - (1 - v)^2, whose factor 2 (1 - v) cancels the
// 1 / m.z growth of GGX's tail; the midpoint rule in (v, phi), phi over
// [0, pi] counted twice (w lies in the xz-plane).
template <typename G> double visible_mean(double cos_w, double alpha, bool beckmann, G g) {
    const int nv = 256, nphi = 64;
    Dir w{std::sqrt(std::max(0.0, 1 - cos_w * cos_w)), 0, cos_w};
    double sum = 0;
    for (int i = 0; i < nv; ++i) {
        double v = (i + 0.5) / nv, u = 1 - (1 - v) * (1 - v);
        double tan2 = beckmann ? -alpha * alpha * std::log1p(-u) : alpha * alpha * u / (1 - u);
        double cz = 1 / std::sqrt(1 + tan2), sz = std::sqrt(tan2) * cz;
        for (int j = 0; j < nphi; ++j) {
            double phi = (j + 0.5) * kPi / nphi;
            Dir m{sz * std::cos(phi), sz * std::sin(phi), cz};
            double wm = dot(w, m);
            if (wm <= 0) continue;
            sum += g(w, m, wm) * wm / cz * 2 * (1 - v);
        }
    }
    Dir n{0, 0, 1};
    return smith_g1(w, n, alpha, beckmann) / cos_w * sum / (nv * double(nphi));
}

// The energy refracted into the coat from cos_w (outside, index ratio ior):
// the visible normals' mean of (1 - F(w.m)) G1(refracted).
double transmittance(double cos_w, double ior, double alpha, bool beckmann) {
    return visible_mean(cos_w, alpha, beckmann, [&](Dir w, Dir m, double wm) {
        double f = fresnel_dielectric(wm, ior);
        double s2t = (1 - wm * wm) / (ior * ior), ct = std::sqrt(1 - s2t);
        Dir t{-w.x / ior + (wm / ior - ct) * m.x, -w.y / ior + (wm / ior - ct) * m.y,
              -w.z / ior + (wm / ior - ct) * m.z};
        return t.z < 0 ? (1 - f) * smith_g1(t, m, alpha, beckmann) : 0.0;
    });
}

// The energy the coat reflects back inside from cos_w (index ratio 1 / ior):
// the visible normals' mean of F(w.m) G1(reflected).
double inner_reflectance_at(double cos_w, double ior, double alpha, bool beckmann) {
    return visible_mean(cos_w, alpha, beckmann, [&](Dir w, Dir m, double wm) {
        Dir r{2 * wm * m.x - w.x, 2 * wm * m.y - w.y, 2 * wm * m.z - w.z};
        return r.z > 0 ? fresnel_dielectric(wm, 1 / ior) * smith_g1(r, m, alpha, beckmann) : 0.0;
    });
}

} // namespace

double fresnel_dielectric(double cos_i, double eta) {
    double sin2_t = (1 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1) return 1;
    double cos_t = std::sqrt(1 - sin2_t);
    double r_s = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    double r_p = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return 0.5 * (r_s * r_s + r_p * r_p);
}

double fresnel_diffuse_reflectance(double eta) {
    // F has a kink at the critical angle (eta < 1): many intervals.
    const int n = 1 << 14;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        double c = double(i) / n;
        double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        sum += w * fresnel_dielectric(c, eta) * c;
    }
    return 2 * sum / (3.0 * n);
}

RoughCoat integrate_rough_coat(double ior, double alpha, bool beckmann) {
    RoughCoat c{};
    for (int i = 0; i < COAT_T_SIZE; ++i)
        c.transmittance[i] =
            transmittance(std::max(1e-6, double(i) / (COAT_T_SIZE - 1)), ior, alpha, beckmann);
    // 2 * integral of r(cos) cos: 4-point Gauss-Legendre on 6 panels each
    // side of the critical cosine, where a nearly smooth coat's r has a kink.
    static const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                0.8611363115940526};
    static const double wt[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                 0.3478548451374538};
    const double cos_c = std::sqrt(1 - 1 / (ior * ior));
    const int panels = 6;
    double sum = 0;
    for (double lo : {0.0, cos_c}) {
        double h = ((lo == 0.0 ? cos_c : 1.0) - lo) / panels;
        for (int p = 0; p < panels; ++p)
            for (int j = 0; j < 4; ++j) {
                double c_w = lo + (p + 0.5 + 0.5 * x[j]) * h;
                sum += wt[j] * 0.5 * h * inner_reflectance_at(c_w, ior, alpha, beckmann) * c_w;
            }
    }
    c.inner_reflectance = 2 * sum;
    return c;
}

void store_coat_transmittance(Material& m, const RoughCoat& coat) {
    for (u32& w : m.coat_t)
        w = 0;
    for (int i = 0; i < COAT_T_SIZE; ++i) {
        double t = std::clamp(coat.transmittance[i], 0.0, 1.0);
        u32 q = u32(std::lround(t * COAT_T_ONE));
        m.coat_t[COAT_T_WORD(i)] |= q << COAT_T_SHIFT(i);
    }
}

} // namespace smallmlt
