#include "render/strata.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace smallmlt {

namespace {

std::uint32_t tiles_along(std::uint32_t pixels, std::uint32_t side) {
    return side ? (pixels + side - 1) / side : 1;
}

} // namespace

double StrataGrid::area(std::uint32_t tile, std::uint64_t pixels) const {
    const FilmTile& t = tiles[tile];
    return double(t.w) * double(t.h) / double(pixels);
}

double strata_large_density(double share) {
    if (!(share > 0) || share >= 1) return 1;
    return (1 - std::pow(1 - share, double(MLT_LARGE_FILM_TRIES))) / share;
}

std::uint32_t strata_count(std::uint32_t width, std::uint32_t height, std::uint32_t side) {
    return tiles_along(width, side) * tiles_along(height, side);
}

StrataGrid strata_grid(std::uint32_t width, std::uint32_t height, std::uint32_t side) {
    StrataGrid g;
    const std::uint32_t sx = side ? side : width, sy = side ? side : height;
    const std::uint32_t columns = tiles_along(width, side), rows = tiles_along(height, side);
    for (std::uint32_t r = 0; r < rows; ++r)
        for (std::uint32_t c = 0; c < columns; ++c) {
            FilmTile t{};
            t.x0 = c * sx;
            t.y0 = r * sy;
            t.w = std::min(sx, width - t.x0);
            t.h = std::min(sy, height - t.y0);
            t.ox = float(double(t.x0) / width);
            t.oy = float(double(t.y0) / height);
            t.sx = float(double(t.w) / width);
            t.sy = float(double(t.h) / height);
            g.tiles.push_back(t);
        }
    g.pixel_tile.resize(std::uint64_t(width) * height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            g.pixel_tile[std::uint64_t(y) * width + x] = (y / sy) * columns + x / sx;
    return g;
}

std::uint32_t strata_side(std::uint32_t asked, std::uint32_t width, std::uint32_t height,
                          std::uint32_t groups) {
    if (asked != kStrataAuto && asked != kStrataPiles) {
        const std::uint32_t n = strata_count(width, height, asked);
        if (n > groups)
            throw UsageError("--strata " + std::to_string(asked) + ": " + std::to_string(n) +
                             " tiles need at least " + std::to_string(n) +
                             " work-groups of chains, and the render has " +
                             std::to_string(groups) + "; use larger tiles or more --threads");
        return asked;
    }
    const std::uint32_t most = groups / kStrataGroupsPerTile;
    const std::uint32_t longest = std::max(width, height);
    for (std::uint32_t side = 8; side < longest; ++side)
        if (strata_count(width, height, side) <= most) return side;
    return 0;
}

std::vector<std::uint32_t> strata_groups(const std::vector<double>& weight, std::uint32_t groups) {
    const std::size_t n = weight.size();
    std::vector<std::uint32_t> out(n, 1);
    if (n == 0 || groups <= n) return out;
    const std::uint32_t rest = groups - std::uint32_t(n);
    double total = std::accumulate(weight.begin(), weight.end(), 0.0);
    std::vector<double> share(n);
    for (std::size_t i = 0; i < n; ++i)
        share[i] = total > 0 ? weight[i] / total * rest : double(rest) / double(n);
    std::uint32_t dealt = 0;
    for (std::size_t i = 0; i < n; ++i) {
        std::uint32_t whole = std::uint32_t(share[i]);
        out[i] += whole;
        dealt += whole;
        share[i] -= whole;
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return share[a] > share[b]; });
    for (std::size_t i = 0; dealt < rest; ++i, ++dealt)
        ++out[order[i % n]];
    return out;
}

std::vector<std::uint32_t> strata_group_tiles(const std::vector<std::uint32_t>& groups,
                                              std::uint32_t count) {
    std::vector<std::uint32_t> tile;
    for (std::uint32_t t = 0; t < groups.size(); ++t)
        tile.insert(tile.end(), groups[t], t);
    tile.resize(count, groups.empty() ? 0 : std::uint32_t(groups.size() - 1));
    return tile;
}

} // namespace smallmlt
