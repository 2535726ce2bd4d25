#include "render/target.hpp"

#include "base/color.hpp"
#include "base/error.hpp"
#include "target_cells.h"

#include <algorithm>

namespace smallmlt {

const char* target_name(Target t) {
    return t == Target::TwoStage ? "two-stage" : "luminance";
}

Target parse_target(const std::string& flag, const std::string& name) {
    if (name == "luminance") return Target::Luminance;
    if (name == "two-stage") return Target::TwoStage;
    throw UsageError(flag + ": '" + name + "' is not a target (luminance or two-stage)");
}

TargetCells target_one_cell() {
    return TargetCells{31u, 1u}; // x >> 31 = y >> 31 = 0 for every pixel
}

std::uint32_t target_cell_count(const TargetCells& cells, std::uint32_t height) {
    if (cells.shift >= 31) return 1;
    std::uint32_t side = 1u << cells.shift;
    return cells.columns * ((height + side - 1) / side);
}

TargetCells target_cells(std::uint32_t width, std::uint32_t height, std::uint64_t samples) {
    std::uint64_t most =
        std::clamp<std::uint64_t>(samples / kTargetSamplesPerCell, 1, kTargetMaxCells);
    for (std::uint32_t shift = 0; shift < 31; ++shift) {
        std::uint32_t side = 1u << shift;
        TargetCells c{shift, (width + side - 1) / side};
        if (target_cell_count(c, height) <= most) return c;
    }
    return target_one_cell();
}

std::vector<float> target_weights(const TargetCells& cells, std::uint32_t width,
                                  std::uint32_t height, const std::vector<double>& rgb_sums) {
    const std::uint32_t n = target_cell_count(cells, height);
    std::vector<double> lum(n, 0.0), px(n, 0.0);
    double total = 0;
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            std::size_t p = 3 * (std::size_t(y) * width + x);
            std::uint32_t c = target_cell(&cells, x, y);
            double l = rgb_luminance(rgb_sums[p], rgb_sums[p + 1], rgb_sums[p + 2]);
            lum[c] += l;
            px[c] += 1;
            total += l;
        }
    std::vector<float> w(n, 1.0f);
    if (!(total > 0)) return w; // no light yet: the luminance
    const double floor = kTargetFloor * total / (double(width) * height);
    double top = 0;
    for (std::uint32_t c = 0; c < n; ++c) {
        lum[c] = std::max(lum[c] / px[c], floor);
        top = std::max(top, lum[c]);
    }
    for (std::uint32_t c = 0; c < n; ++c)
        w[c] = std::max(1.0f, float(top / lum[c]));
    return w;
}

} // namespace smallmlt
