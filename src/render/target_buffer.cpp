#include "render/target_buffer.hpp"

#include "render/omc_cells.hpp"
#include "render/target.hpp"
#include "target_cells.h"

#include <numeric>
#include <stdexcept>
#include <string>

namespace smallmlt {

TargetBuffer::TargetBuffer(const ClContext& cl, std::uint64_t bytes)
    : cl_(cl), weight_(cl, CL_MEM_READ_WRITE, bytes), cells_(target_one_cell()) {
    std::vector<float> ones(weight_.bytes() / sizeof(float), 1.0f);
    weight_.write(cl_, ones.data());
}

namespace {

// The parts every rank gathered, summed over the ranks (the sums a
// decision reads: the MLT part's and the landings).
BurnInParts ranks_parts(RankGroup& ranks, const BurnInParts& parts) {
    const std::size_t pixels = parts.count.size();
    std::vector<double> all(parts.rest);
    all.insert(all.end(), parts.rest_y2.begin(), parts.rest_y2.end());
    all.insert(all.end(), parts.behind.begin(), parts.behind.end());
    all.insert(all.end(), parts.count.begin(), parts.count.end());
    ranks.sum_all(all); // counts are whole numbers, exact in double below 2^53
    BurnInParts sum(pixels);
    auto at = all.begin();
    for (std::vector<double>* v : {&sum.rest, &sum.rest_y2, &sum.behind}) {
        std::copy(at, at + std::ptrdiff_t(v->size()), v->begin());
        at += std::ptrdiff_t(v->size());
    }
    for (std::size_t p = 0; p < pixels; ++p)
        sum.count[p] = std::uint64_t(*at++);
    return sum;
}

} // namespace

void TargetBuffer::fix(RankGroup& ranks, std::uint32_t width, std::uint32_t height,
                       const BurnInParts& parts, bool two_stage, bool omc, const ChainSteps& steps,
                       ChainsStay* stay) {
    const BurnInParts all = ranks_parts(ranks, parts);
    const TargetCells cells = target_cells(
        width, height, std::accumulate(all.count.begin(), all.count.end(), std::uint64_t(0)));
    const std::uint32_t n = target_cell_count(cells, height);
    set(cells, width, height,
        two_stage ? target_weights(cells, width, height, all.rest) : std::vector<float>(n, 1.0f),
        omc ? smallmlt::omc_cells(cells, width, height, all, steps, stay) : std::vector<bool>());
}

void TargetBuffer::set(const TargetCells& cells, std::uint32_t width, std::uint32_t height,
                       std::vector<float> w, const std::vector<bool>& whole) {
    cells_ = cells;
    whole_ = whole;
    omc_cells_ = 0;
    omc_pixels_ = 0;
    for (std::size_t c = 0; c < whole_.size(); ++c)
        if (whole_[c]) {
            w[c] = 0.0f;
            ++omc_cells_;
        }
    if (!whole_.empty())
        for (std::uint32_t y = 0; y < height; ++y)
            for (std::uint32_t x = 0; x < width; ++x)
                omc_pixels_ += omc_pixel(x, y);
    const std::size_t room = weight_.bytes() / sizeof(float); // kTargetMaxCells or one
    if (w.size() > room)
        throw std::logic_error("target: " + std::to_string(w.size()) + " cells, room for " +
                               std::to_string(room) + " (the memory plan's target_cells)");
    w.resize(room, 1.0f);
    weight_.write(cl_, w.data());
}

bool TargetBuffer::omc_pixel(std::uint32_t x, std::uint32_t y) const {
    return !whole_.empty() && whole_[target_cell(&cells_, x, y)];
}

double TargetBuffer::chains_share(const FilmTile& t) const {
    std::uint64_t chains = 0;
    for (std::uint32_t y = t.y0; y < t.y0 + t.h; ++y)
        for (std::uint32_t x = t.x0; x < t.x0 + t.w; ++x)
            chains += !omc_pixel(x, y);
    return double(chains) / (double(t.w) * double(t.h));
}

std::vector<float> TargetBuffer::read() const {
    std::vector<float> w(weight_.bytes() / sizeof(float));
    weight_.read(cl_, w.data());
    return w;
}

} // namespace smallmlt
