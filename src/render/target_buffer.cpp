#include "render/target_buffer.hpp"

#include "render/target.hpp"

namespace smallmlt {

TargetBuffer::TargetBuffer(const ClContext& cl, std::uint64_t bytes)
    : cl_(cl), weight_(cl, CL_MEM_READ_WRITE, bytes), cells_(target_one_cell()) {
    std::vector<float> ones(weight_.bytes() / sizeof(float), 1.0f);
    weight_.write(cl_, ones.data());
}

void TargetBuffer::fix(RankGroup& ranks, std::uint32_t width, std::uint32_t height,
                       const std::vector<double>& rgb_sums, std::uint64_t samples) {
    std::vector<double> all = rgb_sums;
    all.push_back(double(samples)); // ranks may run different threads
    ranks.sum_all(all);
    cells_ = target_cells(width, height, std::uint64_t(all.back()));
    all.pop_back();
    std::vector<float> w = target_weights(cells_, width, height, all);
    w.resize(weight_.bytes() / sizeof(float), 1.0f); // at most kTargetMaxCells
    weight_.write(cl_, w.data());
}

std::vector<float> TargetBuffer::read() const {
    std::vector<float> w(weight_.bytes() / sizeof(float));
    weight_.read(cl_, w.data());
    return w;
}

} // namespace smallmlt
