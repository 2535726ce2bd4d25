// Statistics shared by the tests: the chi-square critical value, normal and
// Student t tails and quantiles, Holm's step-down correction, block sums of
// an image, and Welch's t per block between two sets of independent
// replicas (test/test_render_blocks.cpp).
#pragma once
#include "image/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace smallmlt::test {

// Upper critical value of chi-square with `df` degrees of freedom at
// significance 0.001: exact for 1 and 2, Wilson-Hilferty above (within a
// fraction of a percent for df > 30).
inline double chi2_critical_001(double df) {
    if (df == 1) return 10.828;
    if (df == 2) return 13.816;
    const double z = 3.0902, a = 2.0 / (9.0 * df); // z: standard normal quantile at 0.999
    return df * std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

// P(Z > z) for a standard normal Z.
inline double normal_upper_tail(double z) {
    return 0.5 * std::erfc(z / std::sqrt(2.0));
}

// The standard normal quantile: Phi^-1(p) for 0 < p < 1 (Acklam's rational
// approximation, relative error 1.2e-9, then one Halley step on erfc, which
// brings it to near double precision).
inline double normal_quantile(double p) {
    if (!(p > 0.0 && p < 1.0)) throw std::domain_error("normal_quantile: p outside (0, 1)");
    static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                               -2.759285104469687e+02, 1.383577518672690e+02,
                               -3.066479806614716e+01, 2.506628277459239e+00};
    static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                               -1.556989798598866e+02, 6.680131188771972e+01,
                               -1.328068155288572e+01};
    static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                               -2.400758277161838e+00, -2.549732539343734e+00,
                               4.374664141464968e+00,  2.938163982698783e+00};
    static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                               3.754408661907416e+00};
    const double lo = 0.02425;
    double x;
    if (p < lo) {
        double q = std::sqrt(-2 * std::log(p));
        x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
            ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
    } else if (p <= 1 - lo) {
        double q = p - 0.5, r = q * q;
        x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
            (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
    } else {
        double q = std::sqrt(-2 * std::log(1 - p));
        x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
            ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
    }
    double e = 0.5 * std::erfc(-x / std::sqrt(2.0)) - p;
    double u = e * std::sqrt(2 * M_PI) * std::exp(x * x / 2);
    return x - u / (1 + x * u / 2);
}

// The regularized incomplete beta function I_x(a, b) (continued fraction,
// modified Lentz; Numerical Recipes 6.4).
inline double incomplete_beta(double a, double b, double x) {
    if (x <= 0) return 0;
    if (x >= 1) return 1;
    auto fraction = [](double a, double b, double x) {
        const double tiny = 1e-300;
        auto guard = [&](double v) { return std::fabs(v) < tiny ? tiny : v; };
        double c = 1, d = 1 / guard(1 - (a + b) * x / (a + 1)), h = d;
        for (int m = 1; m <= 500; ++m) {
            double even = m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m));
            d = 1 / guard(1 + even * d);
            c = guard(1 + even / c);
            h *= d * c;
            double odd = -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1));
            d = 1 / guard(1 + odd * d);
            c = guard(1 + odd / c);
            h *= d * c;
            if (std::fabs(d * c - 1) < 1e-15) break;
        }
        return h;
    };
    double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) +
                            b * std::log1p(-x));
    if (x < (a + 1) / (a + b + 2)) return front * fraction(a, b, x) / a;
    return 1 - front * fraction(b, a, 1 - x) / b;
}

// P(|T| > |t|) for Student's t with `df` degrees of freedom (df > 0, not
// necessarily whole).
inline double student_two_sided_p(double t, double df) {
    if (!std::isfinite(t)) return 0;
    return incomplete_beta(df / 2, 0.5, df / (df + t * t));
}

// P(F > f) for Snedecor's F with (d1, d2) degrees of freedom.
inline double f_upper_tail(double f, double d1, double d2) {
    return f <= 0 ? 1.0 : incomplete_beta(d2 / 2, d1 / 2, d2 / (d2 + d1 * f));
}

// The f such that P(F > f) = p (bisection on the tail).
inline double f_critical(double p, double d1, double d2) {
    double lo = 0, hi = 2;
    while (f_upper_tail(hi, d1, d2) > p)
        hi *= 2;
    for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
        double mid = (lo + hi) / 2;
        (f_upper_tail(mid, d1, d2) > p ? lo : hi) = mid;
    }
    return hi;
}

// The t such that P(|T| > t) = p (bisection on the tail).
inline double student_two_sided_critical(double p, double df) {
    double lo = 0, hi = 1;
    while (student_two_sided_p(hi, df) > p)
        hi *= 2;
    for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
        double mid = (lo + hi) / 2;
        (student_two_sided_p(mid, df) > p ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// Holm's step-down correction: which of the hypotheses with p-values `p` are
// rejected at family-wise significance `alpha` (the smallest p against
// alpha / m, the next against alpha / (m - 1), ..., stopping at the first
// that is not rejected).
inline std::vector<bool> holm_reject(const std::vector<double>& p, double alpha) {
    std::vector<std::size_t> order(p.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
    std::vector<bool> reject(p.size(), false);
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (!(p[order[k]] <= alpha / double(p.size() - k))) break;
        reject[order[k]] = true;
    }
    return reject;
}

// Holm-adjusted p-values: the family-wise significance at which each
// hypothesis would just be rejected.
inline std::vector<double> holm_adjusted(const std::vector<double>& p) {
    std::vector<std::size_t> order(p.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
    std::vector<double> adj(p.size());
    double running = 0;
    for (std::size_t k = 0; k < order.size(); ++k) {
        running = std::max(running, std::min(1.0, double(p.size() - k) * p[order[k]]));
        adj[order[k]] = running;
    }
    return adj;
}

// Luminance summed over square blocks of `block` x `block` pixels, row-major
// from the top left (the film's sides must be multiples of `block`).
inline std::vector<double> block_sums(const Image& img, int block) {
    if (img.width % block || img.height % block)
        throw std::invalid_argument("block_sums: film not a multiple of the block");
    const int bw = img.width / block;
    std::vector<double> s(std::size_t(bw) * (img.height / block), 0.0);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            s[std::size_t(y / block) * bw + x / block] +=
                img.luminance(std::size_t(y) * img.width + x);
    return s;
}

// Each block's share of the image's luminance: block_sums / their total, so
// that a scale common to the whole image (MLT's b) cancels.
inline std::vector<double> block_shares(const Image& img, int block) {
    std::vector<double> s = block_sums(img, block);
    double total = std::accumulate(s.begin(), s.end(), 0.0);
    for (double& v : s)
        v = total > 0 ? v / total : 0;
    return s;
}

// Independent replicas of a vector statistic: per-component mean, sample
// variance and standard error of the mean.
class Replicas {
  public:
    void add(const std::vector<double>& v) {
        if (sum_.empty()) sum_.assign(v.size(), 0.0), sum2_.assign(v.size(), 0.0);
        if (v.size() != sum_.size()) throw std::invalid_argument("Replicas: size changed");
        for (std::size_t j = 0; j < v.size(); ++j) {
            sum_[j] += v[j];
            sum2_[j] += v[j] * v[j];
        }
        ++n_;
    }
    int count() const { return n_; }
    std::size_t size() const { return sum_.size(); }
    double mean(std::size_t j) const { return sum_[j] / n_; }
    double variance(std::size_t j) const {
        double m = mean(j);
        return n_ > 1 ? std::max(0.0, (sum2_[j] - n_ * m * m) / (n_ - 1)) : 0.0;
    }
    double se2(std::size_t j) const { return variance(j) / n_; } // squared standard error

  private:
    std::vector<double> sum_, sum2_;
    int n_ = 0;
};

// Welch's t test of equal means per component of two sets of replicas, with
// Holm's correction over the components at family-wise significance alpha.
// Components where both sets have zero variance and equal means are left
// out (p = 1; an empty block); zero variance with unequal means gives p = 0.
struct BlockComparison {
    std::vector<double> diff, se, t, df, p;
    std::vector<bool> reject;
    double alpha = 0;
    std::size_t worst = 0;     // the component with the smallest p
    double min_p_adjusted = 1; // Holm (= Bonferroni) adjusted smallest p
    bool any_reject() const {
        return std::find(reject.begin(), reject.end(), true) != reject.end();
    }
};

inline BlockComparison welch_compare(const Replicas& a, const Replicas& b, double alpha) {
    if (a.size() != b.size() || a.count() < 2 || b.count() < 2)
        throw std::invalid_argument("welch_compare: need two replicas of each, same size");
    BlockComparison c;
    c.alpha = alpha;
    const std::size_t m = a.size();
    c.diff.resize(m), c.se.resize(m), c.t.resize(m), c.df.resize(m), c.p.resize(m);
    for (std::size_t j = 0; j < m; ++j) {
        double va = a.se2(j), vb = b.se2(j), v = va + vb;
        c.diff[j] = a.mean(j) - b.mean(j);
        c.se[j] = std::sqrt(v);
        // Welch-Satterthwaite degrees of freedom.
        double den =
            (va > 0 ? va * va / (a.count() - 1) : 0) + (vb > 0 ? vb * vb / (b.count() - 1) : 0);
        c.df[j] = den > 0 ? v * v / den : double(a.count() + b.count() - 2);
        if (v > 0) {
            c.t[j] = c.diff[j] / c.se[j];
            c.p[j] = student_two_sided_p(c.t[j], c.df[j]);
        } else {
            c.t[j] = c.diff[j] == 0 ? 0 : INFINITY;
            c.p[j] = c.diff[j] == 0 ? 1 : 0;
        }
    }
    c.reject = holm_reject(c.p, alpha);
    c.worst = std::size_t(std::min_element(c.p.begin(), c.p.end()) - c.p.begin());
    c.min_p_adjusted = std::min(1.0, double(m) * c.p[c.worst]);
    return c;
}

// The relative bias of component j that the comparison detects with
// probability 1/2: |bias| = t_crit * se_j, t_crit the two-sided critical
// value at alpha / m (Holm's first step), relative to `reference_j`.
inline double detectable_relative_bias(const BlockComparison& c, std::size_t j, double reference) {
    double t_crit = student_two_sided_critical(c.alpha / double(c.p.size()), c.df[j]);
    return reference > 0 ? t_crit * c.se[j] / reference : INFINITY;
}

} // namespace smallmlt::test
