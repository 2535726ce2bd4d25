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

BurnInPicker::BurnInPicker(const ClContext& cl, cl_program program, std::uint32_t max_n,
                           std::uint32_t tiles, std::uint32_t tile_room)
    : cl_(cl), scan_(cl, program, max_n, sizeof(cl_ulong)), weights_(program, "burnin_weights"),
      pick_(program, "burnin_pick"),
      order_(cl, CL_MEM_READ_ONLY, std::size_t(max_n) * sizeof(cl_uint)),
      first_(cl, CL_MEM_READ_ONLY, (std::size_t(std::max(tiles, tile_room)) + 1) * sizeof(cl_uint)),
      replace_(cl, CL_MEM_READ_ONLY, std::size_t(std::max(tiles, tile_room)) * sizeof(cl_ulong)),
      total_(tiles, 0.0), seen_(tiles, 0) {}

void BurnInPicker::add_round(const ClBuffer& lum, const std::vector<float>& host, std::uint32_t n,
                             const ClBuffer& scan, std::uint64_t seed, std::uint32_t round,
                             std::uint32_t count, const ClBuffer& picks, const PickStrata& strata) {
    const std::size_t tiles = total_.size();
    auto tile_of = [&](std::uint32_t i) {
        return strata.sample_tile ? (*strata.sample_tile)[i] : 0;
    };
    // The samples in the order of their strata (stable), where each stratum's
    // begin, and the luminances burnin_weights keeps: finite and positive.
    std::vector<cl_uint> first(tiles + 1, 0), order(n);
    std::vector<double> sum(tiles, 0.0);
    double round_sum = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        ++first[tile_of(i) + 1];
        if (std::isfinite(host[i]) && host[i] > 0) {
            sum[tile_of(i)] += host[i];
            round_sum += host[i];
        }
    }
    for (std::size_t t = 0; t < tiles; ++t)
        first[t + 1] += first[t];
    std::vector<cl_uint> at(first.begin(), first.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i)
        order[at[tile_of(i)]++] = i;
    std::vector<cl_ulong> replace(tiles, 0);
    bool any = false;
    for (std::size_t t = 0; t < tiles; ++t) {
        if (first[t + 1] == first[t]) continue; // no sample in it: its picks stay
        total_[t] += sum[t];
        replace[t] = burnin_replace_threshold(sum[t], total_[t], seen_[t]++);
        any = any || replace[t] > 0;
    }
    ++rounds_;
    if (!any || count == 0) return;
    first.resize(first_.bytes() / sizeof(cl_uint), first.back());
    replace.resize(replace_.bytes() / sizeof(cl_ulong), 0);
    order.resize(order_.bytes() / sizeof(cl_uint), 0);
    order_.write(cl_, order.data());
    first_.write(cl_, first.data());
    replace_.write(cl_, replace.data());
    weights_.set_args(lum, order_, cl_uint(n), cl_int(burnin_weight_exponent(round_sum)), scan);
    weights_.enqueue(cl_, n);
    scan_.run(scan, scan, n); // in place
    if (!strata.group_tile && !one_tile_.get()) {
        one_tile_ = ClBuffer(cl_, CL_MEM_READ_ONLY, sizeof(cl_uint));
        one_tile_.fill_zero(cl_);
    }
    const ClBuffer& group_tile = strata.group_tile ? *strata.group_tile : one_tile_;
    pick_.set_args(scan, order_, first_, group_tile, cl_uint(strata.group_chains), cl_ulong(seed),
                   cl_uint(round), replace_, cl_uint(count), picks);
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
