// What the render command drives: a method that advances in work units
// (path tracing: one sample per pixel; MLT: one step of every chain) and
// yields an image and a summary.
#pragma once
#include "image/image.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace smallmlt {

class Integrator {
  public:
    virtual ~Integrator() = default;
    // Work before the first unit that belongs to the render (MLT: b, chains).
    virtual void prepare() {}
    virtual void advance(std::uint32_t units) = 0;
    // Units that make `spp` samples (or mutations) per pixel on average.
    virtual std::uint64_t units_for_spp(std::uint32_t spp) const = 0;
    // Samples (or mutations) per pixel so far.
    virtual double spp_done() const = 0;
    virtual Image image() const = 0;
    // Throughput and method-specific figures for the summary line.
    virtual std::string summary(double seconds) const = 0;
    // True when more units cannot change the image (MLT with b = 0).
    virtual bool finished() const { return false; }
    // Remarks for the user after the summary.
    virtual std::vector<std::string> notes() const { return {}; }
};

} // namespace smallmlt
