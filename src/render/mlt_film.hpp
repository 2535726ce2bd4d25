// The MLT film: on the device, words of 32-bit fixed point in up to
// FILM_MAX_BANDS bands (cl/mlt/film.cl), added to by 32-bit atomics; on the
// host, 64-bit sums into which the device's words are drained every
// steps_per_drain steps, before any word could overflow.
//
// The bound. Take a pass of S steps of T threads (K per chain). In each
// step, a chain's proposals splat weights a_i <= 1 and its state gathers the
// stay weight K - sum a_i, so the chain adds exactly K of weight per step;
// the pass ends with every gathered weight splatted (mlt_owed, flush), so
// a pass splats at most T * S of weight in all. A splat of weight w adds
// w * F/lum(F) per channel, and lum(F) >= 0.0722 F_c for non-negative
// F (Rec. 709 luminance; 0.0722 is blue's share), so at most w / 0.0722 per
// channel, rounded up by less than one unit. A pass makes at most T * S
// proposal splats, T * S / K stay splats and T / K flushes: fewer than 3 T S.
// Hence, even if every splat of the pass lands on one pixel, a word holds at
// most T S (2^F / 0.0722 (1 + 2^-10) + 3) (the 2^-10 covers float rounding
// and the 2^-24 rounding of gathered stays), which plan_film keeps below
// 2^32. With Kelemen's weights (cl/mlt/mlt_step.cl) the film has a second
// layer of words, the large steps' own estimates: a large proposal splats
// weight at most 1 there, at most K per chain and step, so the same bound
// holds for each layer's words.
#pragma once
#include "device/memory_plan.hpp"
#include "device/ocl.hpp"

#include <cstdint>
#include <vector>

namespace smallmlt {

// Mutations per pass the film is sized for: 2^20, which leaves F >= 8
// fraction bits (noise of rounding at most 2^-9 of a splat of luminance 1).
constexpr std::uint64_t kFilmPassMutations = std::uint64_t(1) << 20;
constexpr std::uint32_t kFilmMaxFracBits = 16;

struct MltFilmPlan {
    FilmShape shape{};                 // bands, pixels per band, fraction bits
    std::uint32_t steps_per_drain = 0; // S; 0: never (the 64-bit reference)
    bool atomics64 = false;            // FILM_ATOMICS64
};

// The bound above: the largest value a word can reach in a pass of `steps`
// steps of `threads` threads with `frac_bits` fraction bits.
double film_pass_bound(std::uint32_t threads, std::uint32_t steps, std::uint32_t frac_bits);

// S = max(1, pass_mutations / T) steps per drain and the most fraction
// bits F <= kFilmMaxFracBits whose bound stays below 2^32, or, with
// atomics64, one 64-bit band of FILM64_FRAC_BITS drained never; `layers`
// (1, or 2 with Kelemen's weights) per pixel. Throws InputError if the
// bands exceed FILM_MAX_BANDS or not even F = 1 fits.
MltFilmPlan plan_mlt_film(std::uint64_t pixels, std::uint32_t threads, std::uint64_t max_alloc,
                          bool atomics64, std::uint64_t pass_mutations = kFilmPassMutations,
                          std::uint32_t layers = 1);

class MltFilm {
  public:
    MltFilm(const ClContext& cl, std::uint64_t pixels, const MltFilmPlan& plan);

    const MltFilmPlan& plan() const { return plan_; }
    // Band i (band 0 stands in for bands the film does not have).
    const ClBuffer& band(std::uint32_t i) const { return bands_[i < bands_.size() ? i : 0]; }
    // Adds the device's words to the host's sums and zeroes them.
    void drain();
    // Host sums plus the device's words now, per pixel, layer and channel,
    // in units of 2^-frac_bits.
    std::vector<std::uint64_t> read() const;
    // The largest word any drain has seen (a test's view of the bound).
    std::uint64_t peak_word() const { return peak_; }

  private:
    // Adds band b's words to `sums` (pixel order); returns the largest.
    std::uint64_t add_band(std::uint32_t b, std::vector<std::uint64_t>& sums) const;
    const ClContext& cl_;
    MltFilmPlan plan_;
    std::vector<ClBuffer> bands_;
    std::vector<std::uint64_t> host_;
    std::uint64_t peak_ = 0;
};

// Binds the film as FILM_ARGS (cl/mlt/film.cl): FILM_MAX_BANDS bands
// (band 0 in place of those it does not have), then its shape.
#define SMALLMLT_FILM_COUNT(T, name) +1
static_assert(0 FILM_BANDS(SMALLMLT_FILM_COUNT) == FILM_MAX_BANDS, "a parameter per film band");
#undef SMALLMLT_FILM_COUNT
inline void kernel_arg(ClKernel& k, cl_uint& i, const MltFilm& film) {
    std::uint32_t b = 0;
#define SMALLMLT_FILM_BIND(T, name) k.set_arg(i++, film.band(b++));
    FILM_BANDS(SMALLMLT_FILM_BIND)
#undef SMALLMLT_FILM_BIND
    k.set_arg(i++, film.plan().shape);
}

} // namespace smallmlt
