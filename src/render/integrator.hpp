// What the render command drives: a method that advances in work units
// (path tracing: one sample per pixel; MLT: one step of every chain) and
// yields an image and a summary. Its image is made from its tally, so that
// the tallies of several ranks (src/render/ranks.hpp), summed, make theirs.
#pragma once
#include "image/image.hpp"
#include "render/ranks.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace smallmlt {

// What a method has rendered, as numbers that add up over ranks: integers
// (exact fixed-point sums, counts) and reals.
struct Tally {
    std::vector<std::uint64_t> ints;
    std::vector<double> reals;
};

class Integrator {
  public:
    virtual ~Integrator() = default;
    // Work before the first unit that belongs to the render (MLT: b, chains),
    // agreed with the other ranks where it decides anything.
    virtual void prepare(RankGroup&) {}
    virtual void advance(std::uint32_t units) = 0;
    // Units that make rank `rank`'s share of `spp` samples (or mutations)
    // per pixel on average, shared among `ranks` (one: all of them).
    virtual std::uint64_t units_for_spp(std::uint32_t spp, int rank, int ranks) const = 0;
    // Samples (or mutations) per pixel so far.
    virtual double spp_done() const = 0;
    virtual Tally tally() const = 0;
    // The image of a tally: this method's own, or the sum of every rank's.
    virtual Image image_from(const Tally& summed) const = 0;
    Image image() const { return image_from(tally()); }
    // Throughput and method-specific figures for the summary line.
    virtual std::string summary(double seconds) const = 0;
    // True when more units cannot change the image (MLT with b = 0).
    virtual bool finished() const { return false; }
    // Remarks for the user after the summary.
    virtual std::vector<std::string> notes() const { return {}; }
};

} // namespace smallmlt
