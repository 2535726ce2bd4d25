#include "render/programs.hpp"

namespace smallmlt {
namespace {

// Placeholders of the table, filled from the ProgramSpec.
const char* const kSampleSource = "<sample source>";
const char* const kEvaluator = "<evaluator>";

struct Row {
    Stage stage;
    const char* file;
    bool pt, mlt; // in the path tracer's program, in MLT's
};

// clang-format off
const Row kTable[] = {
    {Stage::Core,     "cl/core/shared_types.h",            true,  true},
    {Stage::Core,     "cl/core/rng.h",                     true,  true},
    {Stage::Core,     "cl/core/fixed_point.h",             true,  true},
    {Stage::Core,     "cl/core/burnin_order.h",            true,  true},
    {Stage::Core,     "cl/core/target_cells.h",            true,  true},
    {Stage::Core,     "cl/core/film_step.h",               false, true},
    {Stage::Geometry, "cl/geometry/geometry.cl",           true,  true},
    {Stage::Geometry, "cl/geometry/bvh.cl",                true,  true},
    {Stage::Geometry, "cl/geometry/camera.cl",             true,  true},
    {Stage::Sampling, "cl/sampling/layout.cl",             true,  true},
    {Stage::Sampling, "cl/sampling/sobol.cl",              true,  true},
    {Stage::Sampling, kSampleSource,                       true,  false},
    {Stage::Sampling, "cl/sampling/pss.cl",                false, true},
    {Stage::Sampling, "cl/sampling/strata.cl",             false, true},
    {Stage::Sampling, "cl/sampling/burnin_film.cl",        false, true},
    {Stage::Sampling, "cl/sampling/sample_chain.cl",       false, true},
    {Stage::Sampling, "cl/sampling/numbers.cl",            true,  true},
    {Stage::Shading,  "cl/shading/frame.cl",               true,  true},
    {Stage::Shading,  "cl/shading/texture.cl",             true,  true},
    {Stage::Shading,  "cl/shading/bsdf.cl",                true,  true},
    {Stage::Shading,  "cl/shading/fresnel.cl",             true,  true},
    {Stage::Shading,  "cl/shading/microfacet.cl",          true,  true},
    {Stage::Shading,  "cl/shading/diffuse.cl",             true,  true},
    {Stage::Shading,  "cl/shading/conductor.cl",           true,  true},
    {Stage::Shading,  "cl/shading/rough_conductor.cl",     true,  true},
    {Stage::Shading,  "cl/shading/dielectric.cl",          true,  true},
    {Stage::Shading,  "cl/shading/rough_dielectric.cl",    true,  true},
    {Stage::Shading,  "cl/shading/plastic.cl",             true,  true},
    {Stage::Shading,  "cl/shading/thin_dielectric.cl",     true,  true},
    {Stage::Shading,  "cl/shading/light.cl",               true,  true},
    {Stage::Shading,  "cl/shading/shading.cl",             true,  true},
    {Stage::Path,     "cl/path/path.cl",                   true,  true},
    {Stage::Path,     "cl/path/eval_result.cl",            false, true},
    {Stage::Path,     kEvaluator,                          false, true},
    {Stage::Path,     "cl/path/emission_seen.cl",          false, true},
    {Stage::Mlt,      "cl/mlt/chain_value.cl",             false, true},
    {Stage::Mlt,      "cl/mlt/film.cl",                    false, true},
    {Stage::Mlt,      "cl/mlt/mlt_step.cl",                false, true},
    {Stage::Kernels,  "cl/kernels/pt.cl",                  true,  false},
    {Stage::Kernels,  "cl/kernels/mlt.cl",                 false, true},
};
// clang-format on

} // namespace

std::vector<std::string> program_files(const ProgramSpec& spec, Stage last) {
    const bool pt = spec.program == Program::PathTracer;
    std::vector<std::string> files;
    for (const Row& r : kTable) {
        if (r.stage > last || !(pt ? r.pt : r.mlt)) continue;
        std::string f = r.file;
        if (f == kSampleSource) f = spec.sample_source;
        if (f == kEvaluator) f = spec.evaluator;
        files.push_back(f);
    }
    files.insert(files.end(), spec.extra.begin(), spec.extra.end());
    return files;
}

} // namespace smallmlt
