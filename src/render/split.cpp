#include "render/split.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <cmath>

namespace smallmlt {

const char* split_name(Split s) {
    switch (s) {
    case Split::None:
        return "none";
    case Split::Visible:
        return "visible";
    case Split::Direct:
        return "direct";
    case Split::All:
        return "all";
    case Split::Auto:
        return "auto";
    }
    return "?";
}

Split parse_split(const std::string& flag, const std::string& name) {
    for (Split s : {Split::None, Split::Visible, Split::Direct, Split::All, Split::Auto})
        if (name == split_name(s)) return s;
    throw UsageError(flag + " " + name + ": expected none, visible, direct, all or auto");
}

std::uint32_t split_vertices(Split s) {
    switch (s) {
    case Split::None:
        return 0;
    case Split::Visible:
        return 1;
    case Split::Direct:
        return 2;
    case Split::All:
        return 255; // more vertices than any path has (kMaxDepth 64)
    case Split::Auto:
        return split_vertices(kChainsSplit);
    }
    return 0;
}

std::string split_defines(Split s) {
    return "#define PATH_SPLIT " + std::to_string(split_vertices(s)) + "\n";
}

OmcRates omc_samples_per_step(const SplitCosts& c, double effort) {
    const double film_pixels = c.pixels - c.cell_pixels;
    if (!(c.omc_rays > 0) || !(film_pixels > 0)) return {};
    if (!(c.b > 0) || !(c.mutation_rays > 0)) return {effort > 0 ? 1.0 : 0.0, 0.0};
    const double cm = kChainCorrelation * c.b * c.b * c.pixels * c.pixels * c.mutation_rays;
    double film = std::sqrt(std::max(c.omc_variance, 0.0) * film_pixels * c.omc_rays / cm);
    double cells = c.cell_pixels > 0 && c.cell_rays > 0
                       ? std::sqrt(kPixelStratification * std::max(c.cell_variance, 0.0) *
                                   c.cell_pixels * c.cell_rays / cm)
                       : 0.0;
    if (film + cells > kOmcMaxTimeRatio) { // the parts' optimum under the cap
        const double scale = kOmcMaxTimeRatio / (film + cells);
        film *= scale;
        cells *= scale;
    }
    film = std::max(film, kOmcMinTimeRatio);
    const double share = c.cell_pixels / c.pixels; // of the film, and at least of the time
    if (cells > 0 && share < 1) cells = std::max(cells, share / (1 - share) * (1 + film));
    const double per_time = c.threads * c.mutation_rays * effort;
    OmcRates r;
    r.film = film * per_time / (film_pixels * c.omc_rays);
    if (cells > 0) r.cells = cells * per_time / (c.cell_pixels * c.cell_rays);
    return r;
}

} // namespace smallmlt

namespace smallmlt {

double mlt_part_relative_variance(double mlt_variance, double b, double pixels) {
    return b > 0 && pixels > 0 ? mlt_variance / (pixels * b * b) : 0;
}

double chains_pay_ratio(bool restarting) {
    return restarting ? kRestartPayFactor * kChainsPayRatio : kChainsPayRatio;
}

bool chains_pay(double relative_variance, double behind_specular_share, bool restarting) {
    return relative_variance > chains_pay_ratio(restarting) ||
           behind_specular_share > kChainsPayBehindShare;
}

} // namespace smallmlt
