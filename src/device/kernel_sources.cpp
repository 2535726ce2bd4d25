// Lookup of the embedded kernel files by name.
#include "device/kernel_sources.hpp"

#include <stdexcept>
#include <vector>

namespace smallmlt {
namespace {

std::vector<KernelFiles>& tables() {
    static std::vector<KernelFiles> t{kProductKernelFiles};
    return t;
}

} // namespace

void add_kernel_files(KernelFiles files) {
    tables().push_back(files);
}

const char* kernel_source(const std::string& name) {
    for (const KernelFiles& t : tables())
        for (const KernelFile* f = t.begin; f != t.end; ++f)
            if (name == f->name) return f->text;
    throw std::logic_error("no embedded kernel file " + name);
}

} // namespace smallmlt
