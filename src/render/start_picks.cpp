#include "render/start_picks.hpp"

#include "rng.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace smallmlt {

static_assert(__SIZEOF_INT128__ == 16, "the draw's thresholds need 128-bit products");

namespace {

std::uint64_t morton(std::uint32_t x, std::uint32_t y) {
    std::uint64_t m = 0;
    for (int b = 0; b < 32; ++b)
        m |= (std::uint64_t((x >> b) & 1u) << (2 * b)) |
             (std::uint64_t((y >> b) & 1u) << (2 * b + 1));
    return m;
}

// A luminance's fixed-point weight: lum 2^exponent rounded, at least 1 if
// lum > 0, 0 if lum is 0 or not finite.
std::uint64_t pick_weight(float lum, int exponent) {
    if (!(lum > 0.0f) || !std::isfinite(lum)) return 0;
    return std::max<std::uint64_t>(1,
                                   std::uint64_t(std::llround(std::ldexp(double(lum), exponent))));
}

} // namespace

std::vector<std::uint32_t> start_pick_order(std::uint32_t width, std::uint32_t height,
                                            const StrataGrid& grid) {
    std::vector<std::uint32_t> order(std::size_t(width) * height);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<std::pair<std::uint32_t, std::uint64_t>> key(order.size());
    for (std::uint32_t p : order)
        key[p] = std::make_pair(grid.pixel_tile[p], morton(p % width, p / width));
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    return order;
}

StartPicks::StartPicks(const BurnInFilm& film, std::uint32_t width, std::uint32_t height,
                       const StrataGrid& grid)
    : film_(film), width_(width), height_(height), pixels_(width * height), residue_(pixels_) {
    set_grid(grid);
    // Sample g lies at pixel ((g + offset) mod P) step mod P
    // (burn_in_film_sample): pixel p takes the residue h with h step = p.
    for (std::uint32_t h = 0; h < pixels_; ++h)
        residue_[burn_in_film_sample(film_, pixels_, h + pixels_ - film_.offset).first] = h;
}

void StartPicks::set_grid(const StrataGrid& grid) {
    order_ = start_pick_order(width_, height_, grid);
    tile_begin_.assign(grid.count() + 1, 0);
    for (std::uint32_t p : order_)
        ++tile_begin_[grid.pixel_tile[p] + 1];
    std::partial_sum(tile_begin_.begin(), tile_begin_.end(), tile_begin_.begin());
}

void StartPicks::add_round(std::uint32_t round, const std::vector<float>& lum) {
    if (!rounds_.empty() && round <= rounds_.back())
        throw std::logic_error("start picks: rounds out of order");
    rounds_.push_back(round);
    lum_.push_back(lum);
    for (float y : lum)
        if (y > 0.0f && std::isfinite(y)) {
            total_ += double(y);
            largest_ = std::max(largest_, double(y));
        }
    int e2 = 0;
    std::frexp(total_, &e2); // total < 2^e2
    exponent_ = total_ > 0 ? 62 - e2 : 0;
}

template <class F> void StartPicks::each_in_pixel(std::uint32_t pixel, bool uniform, F f) const {
    const std::uint64_t P = pixels_, per_round = film_.per_round;
    for (std::size_t k = 0; k < rounds_.size(); ++k) {
        // The samples i of the round with (round per_round + i + offset) = h mod P.
        const std::uint64_t base = (std::uint64_t(rounds_[k]) * per_round + film_.offset) % P;
        const std::vector<float>& lum = lum_[k];
        for (std::uint64_t i = (residue_[pixel] + P - base) % P; i < lum.size(); i += P)
            f(rounds_[k], std::uint32_t(i), uniform ? 1 : pick_weight(lum[i], exponent_));
    }
}

bool StartPicks::draw_tile(std::size_t begin, std::size_t end, std::uint32_t u,
                           const std::vector<std::uint32_t>& chains,
                           std::vector<cl_uint2>& out) const {
    std::uint64_t total = 0, count = 0;
    for (std::size_t j = begin; j < end; ++j)
        each_in_pixel(order_[j], false, [&](std::uint32_t, std::uint32_t, std::uint64_t w) {
            total += w;
            ++count;
        });
    const bool uniform = total == 0;
    if (uniform) total = count;
    if (total == 0) return false;
    // Chain q of k takes the sample whose cumulative weight interval holds
    // floor((q + u 2^-32) total / k).
    const unsigned __int128 k = chains.size();
    auto threshold = [&](std::uint64_t q) {
        return std::uint64_t(((unsigned __int128)((q << 32) | u) * total) / (k << 32));
    };
    std::uint64_t acc = 0, q = 0, next = threshold(0);
    for (std::size_t j = begin; j < end && q < chains.size(); ++j)
        each_in_pixel(order_[j], uniform, [&](std::uint32_t r, std::uint32_t i, std::uint64_t w) {
            acc += w;
            for (; q < chains.size() && next < acc; next = threshold(++q))
                out[chains[q]] = cl_uint2{{r, i}};
        });
    return true;
}

std::vector<cl_uint2> StartPicks::draw(const std::vector<std::uint32_t>& group_tile,
                                       std::uint32_t group_chains, std::uint32_t chains,
                                       std::uint64_t seed) const {
    const std::uint32_t tiles = std::uint32_t(tile_begin_.size() - 1);
    std::vector<std::vector<std::uint32_t>> tile_chains(tiles);
    for (std::uint32_t c = 0; c < chains; ++c) {
        std::size_t g =
            group_tile.empty() ? 0 : std::min<std::size_t>(c / group_chains, group_tile.size() - 1);
        tile_chains[group_tile.empty() ? 0 : group_tile[g]].push_back(c);
    }
    const std::uint32_t first_round = rounds_.empty() ? 0 : rounds_.front();
    std::vector<cl_uint2> out(chains, cl_uint2{{first_round, 0}});
    for (std::uint32_t t = 0; t < tiles; ++t) {
        if (tile_chains[t].empty()) continue;
        const std::uint32_t u = rng_u32(rng_key(seed, t, first_round), 0);
        if (!draw_tile(tile_begin_[t], tile_begin_[t + 1], u, tile_chains[t], out))
            draw_tile(0, order_.size(), u, tile_chains[t], out);
    }
    return out;
}

} // namespace smallmlt
