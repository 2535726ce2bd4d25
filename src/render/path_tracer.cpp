#include "render/path_tracer.hpp"

#include "render/programs.hpp"
#include "render/ranks.hpp"

#include <algorithm>
#include <cstdio>

namespace smallmlt {

namespace {

std::uint64_t max_alloc(const ClContext& cl, std::uint64_t given) {
    return given ? given : cl.device().max_alloc_bytes;
}

} // namespace

PathTracer::PathTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed,
                       PtSampler sampler, std::uint64_t max_alloc_bytes,
                       std::uint32_t sample_offset, std::uint32_t sample_stride)
    : cl_(cl), ds_(ds), plan_(plan_pt(ds, max_alloc(cl, max_alloc_bytes))), scene_(cl, ds),
      passes_(cl, ds, scene_, sampler, "", {seed, sample_offset, sample_stride},
              film_bands(std::uint64_t(ds.frame.width) * ds.frame.height, kPtFilmPixelBytes,
                         max_alloc(cl, max_alloc_bytes))
                  .band_pixels,
              plan_.bytes(Buffer::Stats)) {
    const std::uint64_t band_pixels = passes_.band_pixels();
    for (std::uint64_t first = 0; first < pixels(); first += band_pixels) {
        bands_.emplace_back(cl_, CL_MEM_READ_WRITE,
                            std::min(band_pixels, pixels() - first) * kPtFilmPixelBytes);
        bands_.back().fill_zero(cl_);
    }
}

void PathTracer::add_samples(std::uint32_t n) {
    passes_.add_samples(
        n, [&](std::uint64_t b) -> const ClBuffer& { return bands_[b]; },
        [](std::uint64_t, std::uint64_t) {});
}

std::string PathTracer::summary(double seconds) const {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%u spp, %.3f M paths/s, %.3f M rays/s, %llu non-finite dropped",
                  spp(), double(spp()) * double(pixels()) / seconds * 1e-6,
                  double(rays()) / seconds * 1e-6, static_cast<unsigned long long>(nonfinite()));
    return buf;
}

std::vector<std::string> PathTracer::notes() const {
    std::uint64_t n = nonfinite();
    if (n == 0) return {};
    return {std::to_string(n) + " of " + std::to_string(std::uint64_t(spp()) * pixels()) +
            " samples had a NaN or infinite radiance and were dropped (counted as black)"};
}

std::uint64_t PathTracer::units_for_spp(std::uint32_t spp, int rank, int ranks) const {
    return rank_share(spp, rank, ranks);
}

Tally PathTracer::tally() const {
    Tally t;
    t.ints = {spp()};
    t.reals.resize(3 * pixels());
    std::vector<float> sums;
    for (std::size_t b = 0; b < bands_.size(); ++b) {
        sums.resize(bands_[b].bytes() / sizeof(float));
        bands_[b].read(cl_, sums.data());
        std::copy(sums.begin(), sums.end(), t.reals.begin() + 3 * b * passes_.band_pixels());
    }
    return t;
}

Image PathTracer::image_from(const Tally& summed) const {
    Image img(int(ds_.frame.width), int(ds_.frame.height));
    double spp = double(summed.ints.at(0));
    if (spp == 0) return img;
    for (std::size_t i = 0; i < img.rgb.size(); ++i)
        img.rgb[i] = float(summed.reals[i] / spp);
    return img;
}

} // namespace smallmlt
