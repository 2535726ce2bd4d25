#include "render/mlt_film.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <cmath>

namespace smallmlt {

namespace {

constexpr double kWordLimit = 4294967295.0; // 2^32 - 1
constexpr double kBlueShare = 0.0722;       // the least channel weight of path_luminance
constexpr double kFloatSlack = 1.0 + 1.0 / 1024;

} // namespace

double film_pass_bound(std::uint32_t threads, std::uint32_t steps, std::uint32_t frac_bits) {
    double mutations = double(threads) * double(steps);
    return mutations * (std::ldexp(1.0, int(frac_bits)) / kBlueShare * kFloatSlack + 3.0);
}

MltFilmPlan plan_mlt_film(std::uint64_t pixels, std::uint32_t threads, std::uint64_t max_alloc,
                          bool atomics64, std::uint64_t pass_mutations, std::uint32_t layers) {
    MltFilmPlan p;
    p.atomics64 = atomics64;
    const std::uint64_t pixel_bytes = mlt_film_pixel_bytes(atomics64, layers);
    FilmBands split = film_bands(pixels, pixel_bytes, max_alloc);
    if (atomics64 && split.bands > 1)
        throw InputError("the 64-bit reference film needs " + format_bytes(pixels * pixel_bytes) +
                         " in one buffer; the device allows " + format_bytes(max_alloc));
    if (split.bands > FILM_MAX_BANDS)
        throw InputError("the film needs " + std::to_string(split.bands) + " bands of at most " +
                         format_bytes(max_alloc) + " (the device's largest allocation); MLT " +
                         "binds at most " + std::to_string(FILM_MAX_BANDS) +
                         ": use a smaller film");
    p.shape.bands = split.bands;
    p.shape.layers = layers;
    p.shape.band_pixels = std::uint32_t(split.band_pixels);
    if (atomics64) {
        p.shape.frac_bits = FILM64_FRAC_BITS;
        p.steps_per_drain = 0;
    } else {
        std::uint32_t t = std::max(threads, 1u);
        p.steps_per_drain = std::uint32_t(std::max<std::uint64_t>(1, pass_mutations / t));
        std::uint32_t f = kFilmMaxFracBits;
        while (f > 0 && film_pass_bound(t, p.steps_per_drain, f) > kWordLimit)
            --f;
        if (f == 0)
            throw InputError("--threads " + std::to_string(threads) +
                             ": too many for the 32-bit film (one step could overflow it)");
        p.shape.frac_bits = f;
    }
    p.shape.scale = std::ldexp(1.0f, int(p.shape.frac_bits));
    return p;
}

MltFilm::MltFilm(const ClContext& cl, std::uint64_t pixels, const MltFilmPlan& plan)
    : cl_(cl), plan_(plan), host_(3 * plan.shape.layers * pixels, 0) {
    const std::uint64_t pixel_bytes = mlt_film_pixel_bytes(plan.atomics64, plan.shape.layers);
    for (std::uint32_t b = 0; b < plan.shape.bands; ++b) {
        std::uint64_t first = std::uint64_t(b) * plan.shape.band_pixels;
        std::uint64_t n = std::min<std::uint64_t>(plan.shape.band_pixels, pixels - first);
        bands_.emplace_back(cl, CL_MEM_READ_WRITE, n * pixel_bytes);
        bands_.back().fill_zero(cl);
    }
}

namespace {

// Reads a band of words of type T and adds them to sums[first..]; returns
// the largest.
template <typename T>
std::uint64_t add_words(const ClContext& cl, const ClBuffer& band, std::uint64_t* sums) {
    std::vector<T> words(band.bytes() / sizeof(T));
    band.read(cl, words.data());
    std::uint64_t peak = 0;
    for (std::size_t i = 0; i < words.size(); ++i) {
        sums[i] += words[i];
        peak = std::max<std::uint64_t>(peak, words[i]);
    }
    return peak;
}

} // namespace

std::uint64_t MltFilm::add_band(std::uint32_t b, std::vector<std::uint64_t>& sums) const {
    std::uint64_t* at =
        sums.data() + std::size_t(b) * 3 * plan_.shape.layers * plan_.shape.band_pixels;
    return plan_.atomics64 ? add_words<cl_ulong>(cl_, bands_[b], at)
                           : add_words<cl_uint>(cl_, bands_[b], at);
}

void MltFilm::drain() {
    for (std::uint32_t b = 0; b < bands_.size(); ++b) {
        peak_ = std::max(peak_, add_band(b, host_));
        bands_[b].fill_zero(cl_);
    }
}

std::vector<std::uint64_t> MltFilm::read() const {
    std::vector<std::uint64_t> sums = host_;
    for (std::uint32_t b = 0; b < bands_.size(); ++b)
        add_band(b, sums);
    return sums;
}

} // namespace smallmlt
