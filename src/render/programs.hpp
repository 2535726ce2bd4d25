// Which kernel files make which program: one table (programs.cpp), stage by
// stage as cl/ is laid out, so that each file uses only those before it.
#pragma once
#include <string>
#include <vector>

namespace smallmlt {

enum class Program { PathTracer, Mlt };

// The stages of cl/, bottom up (test/layout_test.sh checks that a file
// calls only functions of its own stage and those below).
enum class Stage { Core, Geometry, Sampling, Shading, Path, Mlt, Kernels };

struct ProgramSpec {
    Program program = Program::PathTracer;
    // The path tracer's sample source (cl/sampling/sample_sobol.cl or
    // cl/sampling/sample_omc.cl); MLT's is always the chain's.
    std::string sample_source = "cl/sampling/sample_sobol.cl";
    // What MLT's chains evaluate: the path (cl/path/eval_path.cl) or a test's
    // known target.
    std::string evaluator = "cl/path/eval_path.cl";
    // Files appended after the program's (a test's probe kernels).
    std::vector<std::string> extra;
};

// The program's files in build order, up to and including `last`, then
// spec.extra.
std::vector<std::string> program_files(const ProgramSpec& spec, Stage last = Stage::Kernels);

} // namespace smallmlt
