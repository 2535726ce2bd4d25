#include "render/split.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <cmath>

namespace smallmlt {

const char* split_name(Split s) {
    switch (s) {
    case Split::None: return "none";
    case Split::Visible: return "visible";
    case Split::Direct: return "direct";
    }
    return "?";
}

Split parse_split(const std::string& flag, const std::string& name) {
    for (Split s : {Split::None, Split::Visible, Split::Direct})
        if (name == split_name(s)) return s;
    throw UsageError(flag + " " + name + ": expected none, visible or direct");
}

std::uint32_t split_vertices(Split s) {
    return s == Split::None ? 0 : s == Split::Visible ? 1 : 2;
}

std::string split_defines(Split s) {
    return "#define PATH_SPLIT " + std::to_string(split_vertices(s)) + "\n";
}

double omc_samples_per_step(const SplitCosts& c, double effort) {
    if (!(c.omc_variance > 0) || !(c.omc_rays > 0) || !(c.pixels > 0)) return 0;
    if (!(c.b > 0) || !(c.mutation_rays > 0)) return effort > 0 ? 1.0 : 0.0;
    double a = c.omc_variance * c.pixels * c.omc_rays;
    double cm = kChainCorrelation * c.b * c.b * c.pixels * c.pixels * c.mutation_rays;
    double ratio = std::sqrt(a / cm) * effort; // t_o / t_m
    return ratio * c.threads * c.mutation_rays / (c.pixels * c.omc_rays);
}

} // namespace smallmlt
