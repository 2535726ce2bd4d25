// The test binary's kernel files (test/cl/: probes and a known target),
// embedded into build/gen/test_kernel_sources.cpp and made known to
// kernel_source before any test runs. The product binary has none of them.
#include "device/kernel_sources.hpp"

namespace smallmlt {
extern const KernelFiles kTestKernelFiles;
}

namespace {
const bool kRegistered = (smallmlt::add_kernel_files(smallmlt::kTestKernelFiles), true);
}
