// The MLT render's tallies and its image: the chains' film with what they
// owe, per-tile counts and b, and the image of the chains' part (b times
// the splats per mutation, Kelemen's large steps by b0) plus the OMC
// part's per-pixel means.
#include "render/mlt.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace smallmlt {

MltTally MltRenderer::mlt_tally() const {
    const std::uint32_t layers = film_.plan().shape.layers, tiles = grid_.count();
    MltTally t = MltTally::shaped(pixels(), layers, omc_ != nullptr, tiles);
    // The film with the stay weights the chains have gathered and not yet
    // splatted, which are then taken out again.
    owed(MLT_OWED_ADD);
    std::vector<std::uint64_t> words = film_.read(); // pixel, layer, channel
    owed(MLT_OWED_UNDO);
    cl_.finish("kernel mlt_owed over " + std::to_string(chains()) + " chains");
    const int shift = FILM64_FRAC_BITS - int(film_.plan().shape.frac_bits);
    for (std::size_t i = 0; i < t.film.size(); ++i) {
        const std::size_t at = (i / 3 * layers) * 3 + i % 3;
        t.film[i] = words[at + 3 * FILM_LAYER_CHAINS] << shift;
        if (layers > 1) t.large_film[i] = words[at + 3 * FILM_LAYER_LARGE] << shift;
    }
    tile_counts(t);
    t.burn_in_lum2 = burn_in_.sums().lum2;
    if (omc_) {
        Tally o = omc_->part().tally(); // spp, then sums per pixel and channel
        t.omc_spp = o.ints.at(0);
        t.omc_cell_spp = o.ints.at(1);
        t.omc_sums = o.reals;
        const BurnInParts& b = burn_in_.parts();
        t.burn_in_landed = b.count;
        t.burn_in_omc = b.omc;
        if (split_ == Split::All) // the burn-in's whole paths
            for (std::size_t i = 0; i < b.rest.size(); ++i)
                t.burn_in_omc[i] += b.rest[i];
    }
    return t;
}

std::uint64_t MltRenderer::group_threads(std::size_t g) const {
    const std::uint64_t first = g * kDefaultWorkGroup;
    return first < opt_.threads ? std::min<std::uint64_t>(kDefaultWorkGroup, opt_.threads - first)
                                : 0;
}

void MltRenderer::tile_counts(MltTally& t) const {
    // Each group's row of counters and its threads go to its tile.
    std::vector<std::uint64_t> rows(stats_.bytes() / sizeof(cl_ulong));
    stats_.read(cl_, rows.data());
    const std::vector<std::uint32_t>& group_tile = strata_.group_tiles();
    for (std::size_t g = 0; g < group_tile.size(); ++g) {
        const std::uint32_t tile = group_tile[g];
        t.mutations[tile] += std::uint64_t(steps_run_) * group_threads(g);
        t.large_lum[tile] += rows[g * MLT_STAT_COUNT + MLT_STAT_LARGE_LUM];
        t.large[tile] += rows[g * MLT_STAT_COUNT + MLT_STAT_LARGE];
    }
    t.burn_in_lum = burn_in_.sums().tile_lum;
    t.burn_in_samples = burn_in_.sums().samples;
    t.restart_samples = burn_in_.sums().restart_samples;
}

std::vector<double> MltRenderer::tile_b() const {
    MltTally t = MltTally::shaped(0, 1, false, grid_.count());
    tile_counts(t);
    return tile_b_of(t);
}

std::vector<double> MltRenderer::tile_b_of(const MltTally& t) const {
    std::vector<double> b(grid_.count());
    for (std::uint32_t s = 0; s < grid_.count(); ++s)
        b[s] = mlt_tile_b(t.burn_in_lum[s], t.burn_in_samples, grid_.area(s, pixels()),
                          t.large_lum[s], t.large[s]);
    return b;
}

Tally MltRenderer::tally() const {
    return mlt_tally().to_tally();
}

Image MltRenderer::image_from(const Tally& summed) const {
    return image_of(summed, true, true);
}

Image MltRenderer::part_image(Part part) const {
    return image_of(tally(), part == Part::Mlt, part == Part::Omc);
}

Image MltRenderer::image_of(const Tally& summed, bool mlt, bool omc) const {
    const std::uint32_t tiles = grid_.count();
    MltTally t = MltTally::shaped(pixels(), film_.plan().shape.layers, omc_ != nullptr, tiles);
    t.read(summed);
    Image img(int(ds_.frame.width), int(ds_.frame.height));
    const std::size_t n = 3 * pixels();
    if (mlt) {
        // Per tile: B, and the film's unit in radiance per mutation; the
        // large steps' layer in radiance per uniform sample, its count that
        // of the large steps (p q per mutation) and of the restarts' samples
        // that landed in the tile, and its weights' rate c over that.
        const std::vector<double> b = tile_b_of(t);
        std::vector<double> unit(tiles, 0), large_unit(tiles, 0);
        for (std::uint32_t s = 0; s < tiles; ++s) {
            const double area = double(pixels()) * grid_.area(s, pixels());
            if (t.mutations[s] > 0)
                unit[s] = area / double(t.mutations[s]) / double(1u << FILM64_FRAC_BITS);
            const double uniform = kelemen_large_[s] * double(t.mutations[s]) +
                                   double(t.restart_samples) * grid_.area(s, pixels());
            if (uniform > 0)
                large_unit[s] = kelemen_b0_[s] * kelemen_rate_[s] * area / uniform /
                                double(1u << FILM64_FRAC_BITS);
        }
        const bool large = !t.large_film.empty();
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t s = grid_.pixel_tile[i / 3];
            double v = double(t.film[i]) * b[s] * unit[s];
            if (large) v += double(t.large_film[i]) * large_unit[s];
            img.rgb[i] = float(v);
        }
    }
    if (omc && omc_) {
        // Per-pixel samples and the burn-in's that landed in the pixel.
        const std::uint32_t w = ds_.frame.width;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t p = std::uint32_t(i / 3);
            const bool cell = target_.omc_pixel(p % w, p / w);
            double spp = double(cell ? t.omc_cell_spp : t.omc_spp) + double(t.burn_in_landed[p]);
            if (spp > 0) img.rgb[i] += float((t.omc_sums[i] + t.burn_in_omc[i]) / spp);
        }
    }
    return img;
}

} // namespace smallmlt
