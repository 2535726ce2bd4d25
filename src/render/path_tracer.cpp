#include "render/path_tracer.hpp"

#include "render/programs.hpp"
#include "render/ranks.hpp"

#include <algorithm>
#include <cstdio>

namespace smallmlt {

std::vector<std::string> pt_program_files(PtSampler sampler) {
    ProgramSpec spec;
    spec.sample_source =
        sampler == PtSampler::Sobol ? "cl/sampling/sample_sobol.cl" : "cl/sampling/sample_omc.cl";
    return program_files(spec);
}

namespace {

std::uint64_t max_alloc(const ClContext& cl, std::uint64_t given) {
    return given ? given : cl.device().max_alloc_bytes;
}

} // namespace

PathTracer::PathTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed,
                       PtSampler sampler, std::uint64_t max_alloc_bytes,
                       std::uint32_t sample_offset, std::uint32_t sample_stride)
    : cl_(cl), ds_(ds), seed_(seed), plan_(plan_pt(ds, max_alloc(cl, max_alloc_bytes))),
      program_(cl.build(pt_program_files(sampler), ds.layout.defines())),
      kernel_(program_.p, "pt_render"), own_scene_(std::in_place, cl, ds), scene_(*own_scene_),
      stats_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Stats)),
      band_pixels_(
          film_bands(pixels(), kPtFilmPixelBytes, max_alloc(cl, max_alloc_bytes)).band_pixels),
      sample_offset_(sample_offset), sample_stride_(sample_stride) {
    for (std::uint64_t first = 0; first < pixels(); first += band_pixels_) {
        bands_.emplace_back(cl_, CL_MEM_READ_WRITE,
                            std::min(band_pixels_, pixels() - first) * kPtFilmPixelBytes);
        bands_.back().fill_zero(cl_);
    }
    stats_.fill_zero(cl_);
}

PathTracer::PathTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed,
                       const OmcPart& part)
    : cl_(cl), ds_(ds), seed_(seed), plan_(plan_pt(ds, max_alloc(cl, 0))),
      program_(
          cl.build(pt_program_files(PtSampler::Sobol),
                   ds.layout.defines() + split_defines(part.split) + "#define PT_OMC_PART 1\n")),
      kernel_(program_.p, "pt_render"), scene_(*part.scene),
      stats_(cl, CL_MEM_READ_WRITE, plan_.bytes(Buffer::Stats)),
      band_pixels_(omc_scratch_pixels(pixels())), sample_offset_(part.first_sample),
      sample_stride_(1), host_(3 * pixels(), 0.0) {
    bands_.emplace_back(cl_, CL_MEM_READ_WRITE, band_pixels_ * kPtFilmPixelBytes);
    stats_.fill_zero(cl_);
}

void PathTracer::add_samples(std::uint32_t n) {
    // A device that ends loops after a count per work-item
    // (DeviceInfo::loop_iteration_limit) gets one sample per launch: a path
    // stays well within the count, a pixel's many samples would not. The
    // film is the same, bit for bit: a pixel adds its samples in the same
    // order (the OMC part's host sums, added per launch, round otherwise).
    const std::uint32_t per_launch = cl_.device().loop_iteration_limit ? 1u : n;
    for (std::uint32_t done = 0; done < n; done += per_launch)
        launch(std::min(per_launch, n - done));
}

void PathTracer::launch(std::uint32_t n) {
    cl_ulong seed = seed_;
    cl_uint first_sample = spp_, count = n;
    const bool scratch = !host_.empty();
    std::vector<float> sums(scratch ? 3 * band_pixels_ : 0);
    for (std::uint64_t first = 0, b = 0; first < pixels(); first += band_pixels_, ++b) {
        std::uint64_t size = std::min(band_pixels_, pixels() - first);
        const ClBuffer& band = bands_[scratch ? 0 : b];
        if (scratch) band.fill_zero(cl_);
        kernel_.set_args(scene_, seed, first_sample, count, cl_uint(sample_offset_),
                         cl_uint(sample_stride_), cl_uint(first), cl_uint(size), band, stats_);
        kernel_.enqueue(cl_, size);
        if (!scratch) continue;
        band.read(cl_, sums.data());
        for (std::size_t i = 0; i < 3 * size; ++i)
            host_[3 * first + i] += sums[i];
    }
    cl_.finish("kernel pt_render over " + std::to_string(pixels()) + " pixels");
    spp_ += n;
}

std::string PathTracer::summary(double seconds) const {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%u spp, %.3f M paths/s, %.3f M rays/s, %llu non-finite dropped",
                  spp_, double(spp_) * double(pixels()) / seconds * 1e-6,
                  double(rays()) / seconds * 1e-6, static_cast<unsigned long long>(nonfinite()));
    return buf;
}

std::uint64_t PathTracer::stat(int which) const {
    std::vector<cl_ulong> rows(stats_.bytes() / sizeof(cl_ulong));
    stats_.read(cl_, rows.data());
    std::uint64_t sum = 0;
    for (std::size_t r = 0; r + PT_STAT_COUNT <= rows.size(); r += PT_STAT_COUNT)
        sum += rows[r + which];
    return sum;
}

std::uint64_t PathTracer::nonfinite() const {
    return stat(PT_STAT_NONFINITE);
}

std::vector<std::string> PathTracer::notes() const {
    std::uint64_t n = nonfinite();
    if (n == 0) return {};
    return {std::to_string(n) + " of " + std::to_string(std::uint64_t(spp_) * pixels()) +
            " samples had a NaN or infinite radiance and were dropped (counted as black)"};
}

std::uint64_t PathTracer::rays() const {
    return stat(PT_STAT_RAYS);
}

std::uint64_t PathTracer::units_for_spp(std::uint32_t spp, int rank, int ranks) const {
    return rank_share(spp, rank, ranks);
}

Tally PathTracer::tally() const {
    Tally t;
    t.ints = {spp_};
    if (!host_.empty()) {
        t.reals = host_;
        return t;
    }
    t.reals.resize(3 * pixels());
    std::vector<float> sums;
    for (std::size_t b = 0; b < bands_.size(); ++b) {
        sums.resize(bands_[b].bytes() / sizeof(float));
        bands_[b].read(cl_, sums.data());
        std::copy(sums.begin(), sums.end(), t.reals.begin() + 3 * b * band_pixels_);
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
