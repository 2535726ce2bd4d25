// Kernel sources embedded into the binary at build time (build/gen/
// kernel_sources.cpp, written by src/embed_kernels.sh from cl/).
#pragma once
#include <string>

namespace smallmlt {

// Text of an embedded file such as "cl/path.cl"; throws if unknown.
const char* kernel_source(const std::string& name);

} // namespace smallmlt
