#include "render/path_tracer.hpp"

#include <cstdio>

namespace smallmlt {

std::vector<std::string> pt_program_files(PtSampler sampler) {
    const char* source = sampler == PtSampler::Sobol ? "cl/sample_sobol.cl" : "cl/sample_omc.cl";
    return {"cl/shared_types.h", "cl/rng.cl",    "cl/layout.cl",    source,
            "cl/geometry.cl",    "cl/bvh.cl",    "cl/bsdf.cl",      "cl/light.cl",
            "cl/path.cl",        "cl/camera.cl", "cl/kernels_pt.cl"};
}

PathTracer::PathTracer(const ClContext& cl, const DeviceScene& ds, std::uint64_t seed,
                       PtSampler sampler)
    : cl_(cl), ds_(ds), seed_(seed), plan_(plan_pt(ds)),
      program_(cl.build(pt_program_files(sampler), ds.layout.defines())),
      kernel_(program_.p, "pt_render"), scene_(cl, ds),
      accum_(cl, CL_MEM_READ_WRITE, plan_.bytes("accumulator")),
      ray_count_(cl, CL_MEM_READ_WRITE, plan_.bytes("ray counts")) {
    accum_.fill_zero(cl);
    ray_count_.fill_zero(cl);
}

void PathTracer::add_samples(std::uint32_t n) {
    if (n == 0) return;
    cl_ulong seed = seed_;
    cl_uint first = spp_, count = n;
    kernel_.set_args(scene_.tris, scene_.nodes, scene_.mats, scene_.lights, ds_.frame, seed, first,
                     count, accum_, ray_count_);
    kernel_.run(cl_, pixels());
    spp_ += n;
}

std::string PathTracer::summary(double seconds) const {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%u spp, %.3f M paths/s, %.3f M rays/s, %llu non-finite dropped",
                  spp_, double(spp_) * double(pixels()) / seconds * 1e-6,
                  double(rays()) / seconds * 1e-6, static_cast<unsigned long long>(nonfinite()));
    return buf;
}

std::uint64_t PathTracer::nonfinite() const {
    std::vector<float> acc(pixels() * 4);
    accum_.read(cl_, acc.data());
    std::uint64_t n = 0;
    for (std::size_t p = 0; p < pixels(); ++p)
        n += std::uint64_t(acc[4 * p + 3]);
    return n;
}

std::vector<std::string> PathTracer::notes() const {
    std::uint64_t n = nonfinite();
    if (n == 0) return {};
    return {std::to_string(n) + " of " + std::to_string(std::uint64_t(spp_) * pixels()) +
            " samples had a NaN or infinite radiance and were dropped (counted as black)"};
}

std::uint64_t PathTracer::rays() const {
    std::vector<cl_ulong> counts(pixels());
    ray_count_.read(cl_, counts.data());
    std::uint64_t sum = 0;
    for (cl_ulong c : counts)
        sum += c;
    return sum;
}

Image PathTracer::image() const {
    std::vector<float> acc(pixels() * 4);
    accum_.read(cl_, acc.data());
    Image img(int(ds_.frame.width), int(ds_.frame.height));
    float inv = spp_ ? 1.0f / float(spp_) : 0.0f;
    for (std::size_t p = 0; p < pixels(); ++p)
        for (int c = 0; c < 3; ++c)
            img.rgb[3 * p + c] = acc[4 * p + c] * inv;
    return img;
}

} // namespace smallmlt
