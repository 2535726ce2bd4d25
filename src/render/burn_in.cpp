#include "render/burn_in.hpp"

#include "base/color.hpp"
#include "burnin_order.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <utility>

namespace smallmlt {

BurnInFilm burn_in_film(std::uint64_t pixel_seed, std::uint64_t offset_seed, std::uint32_t pixels,
                        std::uint32_t per_round) {
    std::uint32_t step = std::max(1u, std::uint32_t(0.6180339887498949 * pixels));
    while (std::gcd(step, pixels) != 1)
        ++step;
    BurnInFilm f{};
    f.seed_lo = std::uint32_t(pixel_seed);
    f.seed_hi = std::uint32_t(pixel_seed >> 32);
    f.offset = pixels ? std::uint32_t(offset_seed % pixels) : 0;
    f.step = step;
    f.per_round = per_round;
    return f;
}

std::pair<std::uint32_t, std::uint32_t> burn_in_film_sample(const BurnInFilm& f,
                                                            std::uint32_t pixels, std::uint64_t g) {
    return {burnin_order_pixel(&f, pixels, g), burnin_order_index(&f, pixels, g)};
}

namespace {

// x with a x = 1 mod m (a coprime with m), by the extended Euclidean
// algorithm.
std::uint32_t inverse_mod(std::uint32_t a, std::uint32_t m) {
    std::int64_t r0 = m, r1 = a % m, t0 = 0, t1 = 1;
    while (r1 != 0) {
        const std::int64_t q = r0 / r1;
        r0 = std::exchange(r1, r0 - q * r1);
        t0 = std::exchange(t1, t0 - q * t1);
    }
    return std::uint32_t(((t0 % m) + m) % m);
}

} // namespace

std::uint32_t SequenceStart::at(std::uint32_t pixels, std::uint32_t p) const {
    return first + burnin_order_late(&late, pixels, p);
}

SequenceStart burn_in_omc_start(const BurnInFilm& f, std::uint32_t pixels, std::uint64_t samples) {
    // Pixel p's first sample is g0 = (p step^-1 - offset) mod P; it has had
    // floor(n / P) samples, and one more if g0 < n mod P.
    SequenceStart s;
    s.first = std::uint32_t(samples / pixels);
    s.late.offset = f.offset;
    s.late.inverse = pixels > 1 ? inverse_mod(f.step % pixels, pixels) : 0;
    s.late.count = std::uint32_t(samples % pixels);
    return s;
}

void BurnInParts::add(const std::vector<float>& samples, const std::vector<bool>* in) {
    for (std::size_t i = 0; i + 8 <= samples.size(); i += 8) {
        std::uint32_t pixel;
        std::memcpy(&pixel, &samples[i + 3], sizeof pixel);
        if (in && !in->at(pixel)) continue;
        std::size_t at = 3 * std::size_t(pixel);
        ++count.at(pixel);
        for (int c = 0; c < 3; ++c) {
            omc.at(at + c) += samples[i + c];
            rest.at(at + c) += samples[i + 4 + c];
        }
        double yo = rgb_luminance(samples[i], samples[i + 1], samples[i + 2]);
        double yr = rgb_luminance(samples[i + 4], samples[i + 5], samples[i + 6]);
        omc_y2[pixel] += yo * yo;
        rest_y2[pixel] += yr * yr;
        behind[pixel] += samples[i + 7];
    }
}

BurnInWhole::BurnInWhole(const BurnInParts& parts) : rgb(parts.omc), count(parts.count) {
    for (std::size_t i = 0; i < rgb.size(); ++i)
        rgb[i] += parts.rest.at(i);
}

void BurnInParts::add_whole(const BurnInWhole& other) {
    for (std::size_t i = 0; i < omc.size(); ++i)
        omc[i] += other.rgb.at(i);
    for (std::size_t p = 0; p < count.size(); ++p)
        count[p] += other.count.at(p);
}

double behind_share(double behind_mean, double b) {
    return behind_mean + b > 0 ? behind_mean / (behind_mean + b) : 0;
}

double BurnInParts::behind_specular_share() const {
    const double samples = double(std::accumulate(count.begin(), count.end(), std::uint64_t(0)));
    if (!(samples > 0)) return 0;
    return behind_share(std::accumulate(behind.begin(), behind.end(), 0.0) / samples, mean(rest));
}

double BurnInParts::luminance(const std::vector<double>& sums, std::size_t p) const {
    return rgb_luminance(sums[3 * p], sums[3 * p + 1], sums[3 * p + 2]);
}

double BurnInParts::mean(const std::vector<double>& sums) const {
    double y = 0, samples = 0;
    for (std::size_t p = 0; p < count.size(); ++p) {
        y += luminance(sums, p);
        samples += double(count[p]);
    }
    return samples > 0 ? y / samples : 0;
}

double BurnInParts::variance(const std::vector<double>& sums, const std::vector<double>& y2) const {
    PixelVariance v;
    for (std::size_t p = 0; p < count.size(); ++p)
        v.add(luminance(sums, p), y2[p], count[p]);
    return v.value();
}

void PixelVariance::add(double y, double y2, std::uint64_t n) {
    ++pixels_;
    moment_ += y2;
    samples_ += double(n);
    if (n < 2) return;
    within_ += std::max(0.0, (y2 - y * y / double(n)) / double(n - 1));
    ++used_;
}

double PixelVariance::value() const {
    if (used_ > 0) return double(pixels_) * within_ / double(used_);
    return samples_ > 0 ? double(pixels_) * moment_ / samples_ : 0;
}

double PixelVariance::one_sample(double y) const {
    if (!(samples_ > 0)) return 0;
    // A pixel of n samples, one of them y: sample variance y^2 / n.
    const double per_pixel = y * y * double(pixels_) / samples_;
    return used_ > 0 ? double(pixels_) * per_pixel / double(used_) : per_pixel;
}

} // namespace smallmlt
