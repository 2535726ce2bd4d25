#include "render/omc_cells.hpp"

#include "base/error.hpp"
#include "render/split.hpp"
#include "render/target.hpp"
#include "target_cells.h"

#include <cmath>
#include <limits>
#include <utility>

namespace smallmlt {

bool parse_omc_cells(const std::string& flag, const std::string& name) {
    if (name == "on") return true;
    if (name == "off") return false;
    throw UsageError(flag + " " + name + ": expected on or off");
}

double chain_correlation(double mean, double b, double area, double large_step) {
    if (!(large_step > 0 && b > 0 && area >= 1)) return 1.0;
    return std::max(1.0, mean / (kChainCorrelation * large_step * b * area));
}

std::vector<double> light_areas(const std::vector<double>& means, std::uint32_t width,
                                std::uint32_t height, std::uint32_t reach) {
    // Sums over rectangles from a summed-area table: row y + 1, column x + 1
    // holds the sum of the means above and left of (x, y), inclusive.
    const std::size_t row = std::size_t(width) + 1;
    std::vector<double> sat(row * (height + 1), 0.0);
    for (std::size_t y = 0; y < height; ++y)
        for (std::size_t x = 0; x < width; ++x)
            sat[(y + 1) * row + x + 1] = means[y * width + x] + sat[y * row + x + 1] +
                                         sat[(y + 1) * row + x] - sat[y * row + x];
    std::vector<double> area(means.size(), 1.0);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::size_t p = std::size_t(y) * width + x;
            const std::size_t x0 = x > reach ? x - reach : 0, y0 = y > reach ? y - reach : 0;
            const std::size_t x1 = std::min(width, x + reach + 1),
                              y1 = std::min(height, y + reach + 1);
            const double others = double((x1 - x0) * (y1 - y0) - 1);
            const double sum = sat[y1 * row + x1] - sat[y0 * row + x1] - sat[y1 * row + x0] +
                               sat[y0 * row + x0] - means[p];
            if (means[p] > 0 && others > 0)
                area[p] = 1 + others * std::min(1.0, sum / others / means[p]);
        }
    return area;
}

namespace {

// Calls visit(q) for each pixel q other than (x, y) within `reach` of it on
// a width x height film.
template <class Visit>
void for_each_neighbour(std::uint32_t x, std::uint32_t y, std::uint32_t reach, std::uint32_t width,
                        std::uint32_t height, Visit visit) {
    const std::uint32_t r = reach;
    for (std::uint32_t qy = y > r ? y - r : 0; qy < std::min(height, y + r + 1); ++qy)
        for (std::uint32_t qx = x > r ? x - r : 0; qx < std::min(width, x + r + 1); ++qx)
            if (qx != x || qy != y) visit(std::size_t(qy) * width + qx);
}

} // namespace

std::vector<double> without_lone_pixels(std::vector<double> excess, std::uint32_t width,
                                        std::uint32_t height) {
    const std::vector<double> all = excess;
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            bool beside = false;
            for_each_neighbour(x, y, kLoneReach, width, height,
                               [&](std::size_t q) { beside |= all[q] > 0; });
            if (!beside) excess[std::size_t(y) * width + x] = 0;
        }
    return excess;
}

std::vector<double> neighbour_means(const BurnInParts& parts, std::uint32_t width,
                                    std::uint32_t height) {
    std::vector<double> means(std::size_t(width) * height, 0.0);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            double light = 0, samples = 0;
            for_each_neighbour(x, y, kNeighbourReach, width, height, [&](std::size_t q) {
                light += parts.luminance(parts.rest, q);
                samples += double(parts.count[q]);
            });
            if (samples > 0) means[std::size_t(y) * width + x] = light / samples;
        }
    return means;
}

std::vector<double> stay_excess(const std::vector<double>& means, double b, std::uint32_t width,
                                std::uint32_t height, const ChainSteps& steps) {
    const std::vector<double> area = light_areas(means, width, height, steps.film_pixels);
    std::vector<double> excess(means.size());
    for (std::size_t p = 0; p < means.size(); ++p)
        excess[p] = chain_correlation(means[p], b, area[p], steps.large) - 1;
    return without_lone_pixels(std::move(excess), width, height);
}

namespace {

struct Candidate {
    std::uint32_t cell;
    double light, pixels, variance; // L_c, P_c, V_c
    double stuck;                   // K_c / L_0 (ChainsError)
};

// The chains' squared error on the cells they render, summed over pixels,
// per mutation and in units of tau b P (split.hpp, kChainCorrelation): a
// pixel p of light L_p at correlation tau_p adds L_p L tau_p / tau, with b P
// the chains' light L. Were they to move freely everywhere that is L^2.
// Where they would stay (tau_p = tau max(1, I_p / (tau p b A_p)),
// chain_correlation) it adds the excess L_p (tau_p / tau - 1) L_0, with
// L_0 the chains' light before any cell goes: as b falls, I_p / b grows and
// a small bright area keeps its error. So C = L^2 + K, K summed over the
// pixels where the chains would stay beside another such pixel
// (without_lone_pixels).
struct ChainsError {
    double light = 0, stuck = 0, light_0 = 0; // L, K / L_0, L_0
    double value() const {
        return std::max(light, 0.0) * std::max(light, 0.0) + std::max(stuck, 0.0) * light_0;
    }
    // Without candidate c's cell.
    ChainsError without(const Candidate& c) const {
        return {light - c.light, stuck - c.stuck, light_0};
    }
};

// The cells chosen, S, share one rate of samples per pixel (split.cpp), so
// their error goes as sqrt(P_S V_S), and the chains' as sqrt(C): S
// maximises the gain sqrt(R) (sqrt(C) - sqrt(C without S)) - sqrt(P_S V_S),
// R = kChainsPayRatio. Where the chains move freely everywhere (C = L^2)
// that is sqrt(R) L_S - sqrt(P_S V_S), and for one cell chains_pay's rule,
// r_c < R. Greedily: each cell in turn the one that adds most, keeping the
// best set along the way.
std::vector<std::uint32_t> choose(std::vector<Candidate> open, const ChainsError& film) {
    const double root_r = std::sqrt(kChainsPayRatio), all = std::sqrt(film.value());
    ChainsError left = film;
    double pixels = 0, variance = 0; // of S so far
    std::vector<std::uint32_t> order;
    double best = 0;
    std::size_t best_size = 0;
    while (!open.empty()) {
        std::size_t pick = 0;
        double pick_gain = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < open.size(); ++i) {
            const Candidate& c = open[i];
            const double g = root_r * (all - std::sqrt(left.without(c).value())) -
                             std::sqrt((pixels + c.pixels) * (variance + c.variance));
            if (i == 0 || g > pick_gain) pick = i, pick_gain = g;
        }
        const Candidate& c = open[pick];
        left = left.without(c);
        pixels += c.pixels;
        variance += c.variance;
        order.push_back(c.cell);
        open.erase(open.begin() + std::ptrdiff_t(pick));
        if (pick_gain > best) best = pick_gain, best_size = order.size();
    }
    order.resize(best_size);
    return order;
}

} // namespace

std::vector<bool> omc_cells(const TargetCells& cells, std::uint32_t width, std::uint32_t height,
                            const BurnInParts& parts, const ChainSteps& steps, ChainsStay* stay) {
    const std::uint32_t n = target_cell_count(cells, height);
    std::vector<PixelVariance> variance(n);
    std::vector<double> lum(n, 0.0), stuck(n, 0.0), behind(n, 0.0), samples(n, 0.0), pixels(n, 0.0);
    std::vector<double> stuck_by_neighbours(n, 0.0);
    const double b = parts.mean(parts.rest);
    std::vector<double> means(std::size_t(width) * height, 0.0);
    for (std::size_t p = 0; p < means.size(); ++p)
        if (parts.count[p] > 0) means[p] = parts.luminance(parts.rest, p) / double(parts.count[p]);
    const std::vector<double> excess = stay_excess(means, b, width, height, steps);
    const std::vector<double> excess_by_neighbours =
        stay ? stay_excess(neighbour_means(parts, width, height), b, width, height, steps)
             : std::vector<double>(means.size(), 0.0);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::size_t p = std::size_t(y) * width + x;
            const std::uint32_t c = target_cell(&cells, x, y);
            const double l = parts.luminance(parts.rest, p);
            variance[c].add(l, parts.rest_y2[p], parts.count[p]);
            lum[c] += l;
            stuck[c] += l * excess[p];
            stuck_by_neighbours[c] += l * excess_by_neighbours[p];
            behind[c] += parts.behind[p];
            samples[c] += double(parts.count[p]);
            pixels[c] += 1;
        }
    std::vector<Candidate> open;
    ChainsError film;
    double film_stuck_by_neighbours = 0;
    for (std::uint32_t c = 0; c < n; ++c) {
        if (!(lum[c] > 0)) continue; // no light found: the chains'
        // Sums over the cell's paths to light, as L_c = P_c b_c.
        const double per_path = pixels[c] / samples[c];
        const Candidate cand{c, lum[c] * per_path, pixels[c], variance[c].value(),
                             stuck[c] * per_path};
        film.light += cand.light;
        film.stuck += cand.stuck;
        film_stuck_by_neighbours += stuck_by_neighbours[c] * per_path;
        if (behind_share(behind[c] / samples[c], lum[c] / samples[c]) > kChainsPayBehindShare)
            continue;
        open.push_back(cand);
    }
    film.light_0 = film.light;
    if (stay && film.light > 0) // K / L^2: the stuck sums are K / L_0
        *stay = {film.stuck / film.light, film_stuck_by_neighbours / film.light};
    else if (stay)
        *stay = {};
    std::vector<bool> whole(n, false);
    for (std::uint32_t c : choose(std::move(open), film))
        whole[c] = true;
    return whole;
}

} // namespace smallmlt
