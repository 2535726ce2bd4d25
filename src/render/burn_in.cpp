#include "render/burn_in.hpp"

#include "base/color.hpp"
#include "base/rng.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace smallmlt {

std::uint64_t omc_round_seed(std::uint64_t omc_seed, std::uint32_t round) {
    return rng_round_seed(omc_seed, round);
}

std::uint64_t omc_sample_key(std::uint64_t omc_seed, std::uint32_t round, std::uint32_t index) {
    return rng_key(omc_round_seed(omc_seed, round), index, 0);
}

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
    std::uint64_t h = g + f.offset;
    return {std::uint32_t((h % pixels) * f.step % pixels), std::uint32_t(h / pixels)};
}

std::uint32_t burn_in_film_end(const BurnInFilm& f, std::uint32_t pixels, std::uint64_t samples) {
    return std::uint32_t((std::uint64_t(f.offset) + samples + pixels - 1) / pixels);
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
        double yo = rgb_luminance(samples[i], samples[i + 1], samples[i + 2]);
        double yr = rgb_luminance(samples[i + 4], samples[i + 5], samples[i + 6]);
        omc_y2[pixel] += yo * yo;
        rest_y2[pixel] += yr * yr;
        behind_specular += samples[i + 7];
    }
}

double BurnInParts::behind_specular_share() const {
    const double samples = double(std::accumulate(count.begin(), count.end(), std::uint64_t(0)));
    if (!(samples > 0)) return 0;
    const double s = behind_specular / samples, b = mean(rest);
    return s + b > 0 ? s / (s + b) : 0;
}

double BurnInParts::mean(const std::vector<double>& sums) const {
    double y = 0, samples = 0;
    for (std::size_t p = 0; p < count.size(); ++p) {
        y += rgb_luminance(sums[3 * p], sums[3 * p + 1], sums[3 * p + 2]);
        samples += double(count[p]);
    }
    return samples > 0 ? y / samples : 0;
}

double BurnInParts::variance(const std::vector<double>& sums, const std::vector<double>& y2) const {
    const std::size_t pixels = count.size();
    double within = 0, moment = 0, samples = 0;
    std::size_t used = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        const double n = double(count[p]);
        moment += y2[p];
        samples += n;
        if (count[p] < 2) continue;
        double y = rgb_luminance(sums[3 * p], sums[3 * p + 1], sums[3 * p + 2]);
        within += std::max(0.0, (y2[p] - y * y / n) / (n - 1));
        ++used;
    }
    if (used > 0) return double(pixels) * within / double(used);
    return samples > 0 ? double(pixels) * moment / samples : 0;
}

} // namespace smallmlt
