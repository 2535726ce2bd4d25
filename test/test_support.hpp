// Helpers shared by the tests: one OpenCL context per test binary, scene
// loading with overrides, and small statistics.
#pragma once
#include "base/error.hpp"
#include "device/ocl.hpp"
#include "device/scene_buffers.hpp"
#include "image/image.hpp"
#include "render/mlt.hpp"
#include "render/path_tracer.hpp"
#include "render/programs.hpp"
#include "scene/device_scene.hpp"
#include "scene/scene.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace smallmlt {

// The device's side of an MLT render, for the probes that read or bind its
// buffers (MltRenderer names it its friend).
struct MltInspect {
    static const ClBuffer& state(const MltRenderer& m) { return m.state_; }
    static const ClBuffer& values(const MltRenderer& m) { return m.values_; }
    static const ClBuffer& picks(const MltRenderer& m) { return m.picks_; } // (round, index)
    static std::vector<float> weights(const MltRenderer& m) { return m.target_.read(); }
    static cl_program program(const MltRenderer& m) { return m.program_.p; }
    static const StrataBuffer& strata(const MltRenderer& m) { return m.strata_; }
    static const TargetBuffer& target(const MltRenderer& m) { return m.target_; }
    // The split's OMC part (null without a split).
    static const OmcPartTracer* omc_part(const MltRenderer& m) {
        return m.omc_ ? &m.omc_->part() : nullptr;
    }
};

} // namespace smallmlt

namespace smallmlt::test {

// Device 0, created once (kernel builds are cached per source by PoCL).
inline const ClContext& cl() {
    static ClContext ctx(0);
    return ctx;
}

// The pixel of each chain's current state, in its tile (probe_chain_pixel
// of test/cl/probe_mlt.cl, which the renderer's hooks must have added).
inline std::vector<cl_uint> chain_pixels(const MltRenderer& mlt, const Frame& frame) {
    const std::uint32_t chains = mlt.chains();
    ClBuffer out(cl(), CL_MEM_WRITE_ONLY, chains * sizeof(cl_uint));
    ClKernel k(MltInspect::program(mlt), "probe_chain_pixel");
    k.set_args(frame, MltInspect::strata(mlt), MltInspect::state(mlt), cl_uint(chains), out);
    k.run(cl(), chains);
    std::vector<cl_uint> pixel(chains);
    out.read(cl(), pixel.data());
    return pixel;
}

// Skips the calling test, saying why, on a device without 64-bit atomics:
// the 64-bit reference film (--film-atomics 64) needs them.
#define SKIP_WITHOUT_INT64_ATOMICS()                                                               \
    if (!::smallmlt::test::cl().device().int64_atomics)                                            \
    GTEST_SKIP() << ::smallmlt::test::cl().device().name                                           \
                 << " lacks cl_khr_int64_base_atomics, which the 64-bit reference film needs"

// The program of the probes of test/cl/probe.cl: the stages up to geometry,
// then the probes (no scene's layout defines).
inline cl_program probe_program() {
    return cl().build(
        program_files({Program::PathTracer, "", "", {"test/cl/probe.cl"}}, Stage::Geometry), "");
}

// A scene from scenes/ (tests run from the repository root).
inline Scene scene(const std::string& name, int width, int height, int depth = -1) {
    Scene s = load_scene("scenes/" + name + ".scene");
    s.width = width;
    s.height = height;
    if (depth >= 0) s.depth = depth;
    return s;
}

// A scene with no geometry whose sample layout is `f`: enough for probe
// kernels and for the known-target evaluator (test/cl/eval_target.cl).
// Features of a scene with materials of `types`, `lights` emitters and
// depth `depth`.
inline SceneFeatures features(std::initializer_list<std::uint32_t> types, std::uint32_t lights,
                              int depth) {
    SceneFeatures f;
    for (std::uint32_t t : types)
        f.with(t);
    f.num_lights = lights;
    f.depth = depth;
    return f;
}

inline DeviceScene layout_only_scene(const SceneFeatures& f, int width = 4, int height = 4) {
    DeviceScene ds;
    ds.layout = make_layout(f);
    ds.frame.width = width;
    ds.frame.height = height;
    ds.frame.depth = f.depth;
    return ds;
}

// MLT as the paper has it: the chains render all light (no split), splat
// expected values (no Kelemen weights) and take large steps at 0.5. The
// tests of the chains and of their image are written against it; the
// library's defaults (MltOptions{}) are the command line's.
// The furnace: Kd 0.5 and Ke 1 on every face of a closed box, so light
// reaching the camera after L vertices is 0.5^L; this sums it over L = lo
// .. hi.
inline double furnace_sum(int lo, int hi) {
    double s = 0;
    for (int l = lo; l <= hi; ++l)
        s += std::pow(0.5, l);
    return s;
}

// The paper's MLT: no split, expected values, no strata.
inline MltOptions plain_mlt() {
    MltOptions opt;
    opt.split = Split::None;
    opt.kelemen = false;
    opt.large_step = 0.5f;
    opt.strata = 0;
    return opt;
}

// Path-traced image of `ds` at `spp` samples per pixel.
inline Image render_pt(const DeviceScene& ds, std::uint64_t seed, std::uint32_t spp,
                       PtSampler sampler = PtSampler::Sobol) {
    PathTracer pt(cl(), ds, seed, sampler);
    pt.add_samples(spp);
    return pt.image();
}

// `batches` path-traced images of `ds`, each the mean of `spp / batches`
// samples per pixel of one render (seed `seed`) with the random sampler:
// independent replicas, since a render's samples are numbered and never
// repeat (a Sobol render's batches are not: they share a scramble). A batch
// is the difference of the running sums before and after it.
inline std::vector<Image> render_pt_batches(const DeviceScene& ds, std::uint64_t seed,
                                            std::uint32_t spp, int batches) {
    PathTracer pt(cl(), ds, seed, PtSampler::Random);
    const std::uint32_t per = spp / std::uint32_t(batches);
    std::vector<Image> out;
    std::vector<double> before;
    for (int k = 0; k < batches; ++k) {
        pt.add_samples(per);
        Image img = pt.image();
        before.resize(img.rgb.size(), 0.0);
        Image batch(img.width, img.height);
        for (std::size_t i = 0; i < img.rgb.size(); ++i) {
            double sum = double(img.rgb[i]) * pt.spp();
            batch.rgb[i] = float((sum - before[i]) / per);
            before[i] = sum;
        }
        out.push_back(batch);
    }
    return out;
}

// Runs probe_lazy_eager (test/cl/probe_mlt.cl, which `mlt` must have
// been built with) on every chain with proposal key seed 99: per chain the
// lazily evaluated proposal, the same materialized and replayed, and the
// committed state replayed (F, live bounces in w).
inline std::vector<cl_float4> lazy_eager_committed(const MltRenderer& mlt, const DeviceScene& ds,
                                                   std::uint32_t chains) {
    ClBuffer eager(cl(), CL_MEM_READ_WRITE, MltInspect::state(mlt).bytes());
    ClBuffer out(cl(), CL_MEM_WRITE_ONLY, std::size_t(chains) * 3 * sizeof(cl_float4));
    SceneBuffers sb(cl(), ds);
    ClKernel k(MltInspect::program(mlt), "probe_lazy_eager");
    k.set_args(sb, MltInspect::state(mlt), MltInspect::values(mlt), eager, cl_uint(chains),
               cl_ulong(99), out);
    k.run(cl(), chains);
    std::vector<cl_float4> f(std::size_t(chains) * 3);
    out.read(cl(), f.data());
    return f;
}

// Makes chains 0, every, 2 every, ... of `mlt` (prepared) stay where they
// are from now on, whatever the seed: their G(x) becomes 1e30 (grey), which
// no path comes near, so every proposal's a = I(y)/I(x) is below 1e-20,
// the stay weight K - sum a rounds to K in float, and the step's choice
// u < K never passes it. Returns the chains held.
inline std::vector<std::uint32_t> hold_chains(const MltRenderer& mlt, std::uint32_t every) {
    std::vector<ChainValue> v(mlt.chains());
    MltInspect::values(mlt).read(cl(), v.data());
    std::vector<std::uint32_t> held;
    for (std::uint32_t c = 0; c < mlt.chains(); c += every) {
        v[c].rgb[0] = v[c].rgb[1] = v[c].rgb[2] = 1e30f;
        held.push_back(c);
    }
    MltInspect::values(mlt).write(cl(), v.data());
    return held;
}

// The current run of rejections of each chain of `mlt`.
inline std::vector<std::uint32_t> chain_runs(const MltRenderer& mlt) {
    std::vector<ChainValue> v(mlt.chains());
    MltInspect::values(mlt).read(cl(), v.data());
    std::vector<std::uint32_t> runs;
    for (const ChainValue& x : v)
        runs.push_back(x.meta >> CHAIN_RUN_SHIFT);
    return runs;
}

// How far an MLT image's mean luminance may stray from b by the film's
// rounding alone (b cancels from it): 1e-6 for the 2^-24 rounding of
// weights, plus 5 standard deviations of the film's stochastic rounding:
// each added word errs by at most a quarter unit squared in variance,
// units of 2^-F, weighted at most 0.7152 (green's share) in luminance,
// over about 3 words per step for each flush or read, beside the steps'
// atomics; relative to the image's total weight, the mutations.
inline double film_mean_tolerance(const MltRenderer& m) {
    MltStats s = m.stats();
    if (s.mutations == 0) return 0;
    const MltFilmPlan& p = m.film().plan();
    double drains = p.steps_per_drain ? double(m.iterations() / p.steps_per_drain) : 0.0;
    double words = double(s.atomics) + 3.0 * m.chains() * (drains + 2);
    double sd = 0.7152 * 0.5 * std::sqrt(words) / double(p.shape.scale) / double(s.mutations);
    return 1e-6 + 5 * sd;
}

// A scratch directory under build/, emptied per call site.
inline std::string scratch_dir(const std::string& name) {
    std::string dir = "build/test-scratch/" + name;
    std::string cmd = "rm -rf '" + dir + "' && mkdir -p '" + dir + "'";
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("cannot make " + dir);
    return dir;
}

// Each quadrant's share of the image's total luminance (top left, top right,
// bottom left, bottom right): where the light went, whatever the scale.
inline std::array<double, 4> quadrant_shares(const Image& img) {
    std::array<double, 4> q{};
    double total = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            double l = img.luminance(std::size_t(y) * img.width + x);
            q[(2 * y / img.height) * 2 + 2 * x / img.width] += l;
            total += l;
        }
    for (double& v : q)
        v = total > 0 ? v / total : 0;
    return q;
}

inline void write_file(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

// The message of the InputError that f throws, or "" if it throws none.
template <class F> std::string input_error_of(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// `msg` from the first `from` in it on; all of it where there is none.
inline std::string message_from(const std::string& msg, const std::string& from) {
    const std::size_t at = msg.find(from);
    return at == std::string::npos ? msg : msg.substr(at);
}

} // namespace smallmlt::test
