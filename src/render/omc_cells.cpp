#include "render/omc_cells.hpp"

#include "base/error.hpp"
#include "render/split.hpp"
#include "render/target.hpp"
#include "target_cells.h"

namespace smallmlt {

bool parse_omc_cells(const std::string& flag, const std::string& name) {
    if (name == "on") return true;
    if (name == "off") return false;
    throw UsageError(flag + " " + name + ": expected on or off");
}

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
    std::vector<bool> whole(n, false);
    for (std::uint32_t c = 0; c < n; ++c) {
        if (!(lum[c] > 0)) continue; // no light found: the chains'
        const double b = lum[c] / samples[c];
        const double r = mlt_part_relative_variance(variance[c].value(), b, pixels[c]);
        whole[c] = !chains_pay(r, behind_share(behind[c] / samples[c], b));
    }
    return whole;
}

} // namespace smallmlt
