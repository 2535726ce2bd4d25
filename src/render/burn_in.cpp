#include "render/burn_in.hpp"

#include "base/color.hpp"
#include "base/rng.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace smallmlt {

namespace {

// The kernels' rng_key (cl/rng.cl).
std::uint64_t rng_key(std::uint64_t seed, std::uint32_t a, std::uint32_t b) {
    return rng_mix64(seed + rng_mix64((std::uint64_t(a) << 32) | b));
}

} // namespace

std::uint64_t omc_round_seed(std::uint64_t omc_seed, std::uint32_t round) {
    return derive_seed(omc_seed, round);
}

std::uint64_t omc_sample_key(std::uint64_t omc_seed, std::uint32_t round, std::uint32_t index) {
    return rng_key(omc_round_seed(omc_seed, round), index, 0);
}

int burnin_weight_exponent(double sum) {
    if (!(sum > 0) || !std::isfinite(sum)) return 0;
    int e;
    std::frexp(sum, &e); // sum < 2^e
    return 62 - e;
}

std::uint64_t burnin_replace_threshold(double s, double total, std::uint32_t round) {
    const double one = 4294967296.0;
    if (!(total > 0)) return std::uint64_t(std::llround(one / (double(round) + 1)));
    if (!(s > 0)) return 0;
    if (s >= total) return std::uint64_t(one);
    return std::min(std::uint64_t(one), std::uint64_t(std::llround(s / total * one)));
}

BurnInPicker::BurnInPicker(const ClContext& cl, cl_program program, std::uint32_t max_n)
    : cl_(cl), scan_(cl, program, max_n, sizeof(cl_ulong)), weights_(program, "burnin_weights"),
      pick_(program, "burnin_pick") {}

void BurnInPicker::add_round(const ClBuffer& lum, const std::vector<float>& host, std::uint32_t n,
                             const ClBuffer& scan, std::uint64_t seed, std::uint32_t count,
                             const ClBuffer& picks) {
    // The luminances burnin_weights keeps: finite and positive.
    double sum = 0;
    for (std::uint32_t i = 0; i < n; ++i)
        if (std::isfinite(host[i]) && host[i] > 0) sum += host[i];
    total_ += sum;
    const std::uint32_t round = rounds_++;
    std::uint64_t replace = burnin_replace_threshold(sum, total_, round);
    if (replace == 0 || count == 0) return;
    weights_.set_args(lum, cl_uint(n), cl_int(burnin_weight_exponent(sum)), scan);
    weights_.enqueue(cl_, n);
    scan_.run(scan, scan, n); // in place
    pick_.set_args(scan, cl_uint(n), cl_ulong(seed), cl_uint(round), cl_ulong(replace),
                   cl_uint(count), picks);
    pick_.run(cl_, count);
}

void BurnInParts::add(const std::vector<float>& samples) {
    for (std::size_t i = 0; i + 8 <= samples.size(); i += 8) {
        std::uint32_t pixel;
        std::memcpy(&pixel, &samples[i + 3], sizeof pixel);
        std::size_t at = 3 * std::size_t(pixel);
        ++count.at(pixel);
        for (int c = 0; c < 3; ++c) {
            omc.at(at + c) += samples[i + c];
            rest.at(at + c) += samples[i + 4 + c];
        }
        double y = rgb_luminance(samples[i], samples[i + 1], samples[i + 2]);
        omc_sum2 += y * y;
    }
}

double BurnInParts::variance(const std::vector<double>& sums, double sum2, double samples) {
    const double pixels = double(sums.size() / 3), per = pixels / samples;
    double mu2 = 0;
    for (std::size_t p = 0; p < sums.size(); p += 3) {
        double mu = per * rgb_luminance(sums[p], sums[p + 1], sums[p + 2]);
        mu2 += mu * mu;
    }
    return std::max(0.0, per * sum2 * (1 + per) - mu2);
}

} // namespace smallmlt
