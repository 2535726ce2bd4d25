#include "render/omc_cells.hpp"

#include "base/error.hpp"
#include "render/split.hpp"
#include "render/target.hpp"
#include "target_cells.h"

#include <cmath>
#include <limits>
#include <utility>

namespace smallmlt {

bool parse_omc_cells(const std::string& flag, const std::string& name) {
    if (name == "on") return true;
    if (name == "off") return false;
    throw UsageError(flag + " " + name + ": expected on or off");
}

namespace {

struct Candidate {
    std::uint32_t cell;
    double light, pixels, variance; // L_c = P_c b_c, P_c, V_c
};

// The cells chosen, S, share one rate of samples per pixel (split.cpp), so
// their error goes as sqrt(P_S V_S), and the chains' as their light: S
// maximises the gain sqrt(R) L_S - sqrt(P_S V_S), R = kChainsPayRatio. For
// one cell that is chains_pay's rule, r_c < R. Greedily: each cell in turn
// the one that adds most, keeping the best set along the way.
std::vector<std::uint32_t> choose(std::vector<Candidate> open) {
    const double root_r = std::sqrt(kChainsPayRatio);
    double light = 0, pixels = 0, variance = 0; // of S so far
    std::vector<std::uint32_t> order;
    double best = 0;
    std::size_t best_size = 0;
    while (!open.empty()) {
        std::size_t pick = 0;
        double pick_gain = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < open.size(); ++i) {
            const Candidate& c = open[i];
            const double g = root_r * (light + c.light) -
                             std::sqrt((pixels + c.pixels) * (variance + c.variance));
            if (i == 0 || g > pick_gain) pick = i, pick_gain = g;
        }
        light += open[pick].light;
        pixels += open[pick].pixels;
        variance += open[pick].variance;
        order.push_back(open[pick].cell);
        open.erase(open.begin() + std::ptrdiff_t(pick));
        if (pick_gain > best) best = pick_gain, best_size = order.size();
    }
    order.resize(best_size);
    return order;
}

} // namespace

std::vector<bool> omc_cells(const TargetCells& cells, std::uint32_t width, std::uint32_t height,
                            const BurnInParts& parts) {
    const std::uint32_t n = target_cell_count(cells, height);
    std::vector<PixelVariance> variance(n);
    std::vector<double> lum(n, 0.0), behind(n, 0.0), samples(n, 0.0), pixels(n, 0.0);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::size_t p = std::size_t(y) * width + x;
            const std::uint32_t c = target_cell(&cells, x, y);
            const double l = parts.luminance(parts.rest, p);
            variance[c].add(l, parts.rest_y2[p], parts.count[p]);
            lum[c] += l;
            behind[c] += parts.behind[p];
            samples[c] += double(parts.count[p]);
            pixels[c] += 1;
        }
    std::vector<Candidate> open;
    for (std::uint32_t c = 0; c < n; ++c) {
        if (!(lum[c] > 0)) continue; // no light found: the chains'
        const double b = lum[c] / samples[c];
        if (behind_share(behind[c] / samples[c], b) > kChainsPayBehindShare) continue;
        open.push_back({c, pixels[c] * b, pixels[c], variance[c].value()});
    }
    std::vector<bool> whole(n, false);
    for (std::uint32_t c : choose(std::move(open)))
        whole[c] = true;
    return whole;
}

} // namespace smallmlt
