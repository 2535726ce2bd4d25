#include "render/mlt_tally.hpp"

#include <stdexcept>

namespace smallmlt {

MltTally MltTally::shaped(std::uint64_t pixels, std::uint32_t layers, bool split,
                          std::uint32_t tiles) {
    MltTally t;
    t.film.assign(3 * pixels, 0);
    for (std::vector<std::uint64_t>* v : {&t.mutations, &t.burn_in_lum, &t.large_lum, &t.large})
        v->assign(tiles, 0);
    if (layers > 1) t.large_film.assign(3 * pixels, 0);
    if (split) {
        t.omc_sums.assign(3 * pixels, 0);
        t.burn_in_landed.assign(pixels, 0);
        t.burn_in_omc.assign(3 * pixels, 0);
    }
    return t;
}

namespace {

// Appends each field to a Tally's integers or reals.
struct Writer {
    Tally& t;
    void operator()(std::uint64_t v) { t.ints.push_back(v); }
    void operator()(double v) { t.reals.push_back(v); }
    template <typename E> void operator()(const std::vector<E>& v) {
        for (E e : v)
            (*this)(e);
    }
};

// Reads each field from a Tally's integers or reals, in the same order.
struct Reader {
    const Tally& t;
    std::size_t ints = 0, reals = 0;
    void operator()(std::uint64_t& v) { v = t.ints.at(ints++); }
    void operator()(double& v) { v = t.reals.at(reals++); }
    template <typename E> void operator()(std::vector<E>& v) {
        for (E& e : v)
            (*this)(e);
    }
};

} // namespace

Tally MltTally::to_tally() const {
    Tally t;
    visit(*this, Writer{t});
    return t;
}

void MltTally::read(const Tally& t) {
    Reader r{t};
    try {
        visit(*this, r);
    } catch (const std::out_of_range&) {
        throw std::logic_error("an MLT tally shorter than its shape");
    }
    if (r.ints != t.ints.size() || r.reals != t.reals.size())
        throw std::logic_error("an MLT tally longer than its shape");
}

} // namespace smallmlt
