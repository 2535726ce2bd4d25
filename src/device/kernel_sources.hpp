// Kernel sources embedded into the binary at build time: the product's
// (cl/, written into build/gen/kernel_sources.cpp by
// src/device/embed_kernels.sh) and those a test binary adds (test/cl/).
#pragma once
#include <string>

namespace smallmlt {

struct KernelFile {
    const char* name; // its path in the repository, e.g. "cl/path/path.cl"
    const char* text;
};
struct KernelFiles {
    const KernelFile *begin, *end;
};

// The product's kernel files (every file of cl/).
extern const KernelFiles kProductKernelFiles;

// Makes `files` known to kernel_source as well (a test binary's probes).
void add_kernel_files(KernelFiles files);

// Text of an embedded file; throws std::logic_error if unknown.
const char* kernel_source(const std::string& name);

} // namespace smallmlt
