// What an MLT render has rendered, by name: the numbers that add up over
// ranks (src/render/ranks.hpp), and their one order in a Tally.
#pragma once
#include "render/integrator.hpp"

#include <cstdint>
#include <vector>

namespace smallmlt {

struct MltTally {
    // Per pixel and channel, the film's chains' layer with what the chains
    // owe, and its large steps' layer (Kelemen's weights; else empty), in
    // units of 2^-FILM64_FRAC_BITS.
    std::vector<std::uint64_t> film, large_film;
    // Per tile of the strata (src/render/strata.hpp; one without): the
    // mutations of its chains, and its normalization's samples in
    // MLT_B_FRAC_BITS fixed point: the luminance sum of the burn-in's
    // samples that landed in it, and its large steps' sum and count.
    std::vector<std::uint64_t> mutations, burn_in_lum, large_lum, large;
    // The burn-in's samples on the whole film, and their sum of squared
    // luminances.
    std::uint64_t burn_in_samples = 0;
    // Of those, the restarts' (--restart), which with Kelemen's weights are
    // also large steps' samples in large_film.
    std::uint64_t restart_samples = 0;
    double burn_in_lum2 = 0;
    // With a split: the OMC part's samples per pixel (on the film, and on the
    // pixels of the cells it renders whole) and per pixel and channel its
    // sums; per pixel the burn-in's samples that landed in it, and per pixel
    // and channel their OMC parts (with Split::All, whole paths).
    std::uint64_t omc_spp = 0, omc_cell_spp = 0;
    std::vector<double> omc_sums;
    std::vector<std::uint64_t> burn_in_landed;
    std::vector<double> burn_in_omc;

    // An empty tally of a film of `pixels` in `layers` layers and `tiles`
    // tiles, with or without a split's parts.
    static MltTally shaped(std::uint64_t pixels, std::uint32_t layers, bool split,
                           std::uint32_t tiles = 1);
    Tally to_tally() const;
    // Reads a tally of this one's shape; throws std::logic_error if its
    // size is not this shape's.
    void read(const Tally& t);

    // Calls v on every field in the one order of a Tally: v(u64&) or
    // v(double&) for a number, v(vector&) for a list.
    template <typename T, typename V> static void visit(T& t, V&& v) {
        v(t.film);
        v(t.large_film);
        v(t.mutations);
        v(t.burn_in_lum);
        v(t.burn_in_samples);
        v(t.restart_samples);
        v(t.large_lum);
        v(t.large);
        v(t.burn_in_lum2);
        v(t.omc_spp);
        v(t.omc_cell_spp);
        v(t.omc_sums);
        v(t.burn_in_landed);
        v(t.burn_in_omc);
    }
};

} // namespace smallmlt
