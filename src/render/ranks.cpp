#include "render/ranks.hpp"

#include "base/rng.hpp"

#include <unistd.h>

namespace smallmlt {

namespace {

constexpr std::uint64_t kPurposeRank = 0x52414E4Bu; // "RANK"

} // namespace

std::string SingleRank::host() const {
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0) return "localhost";
    return name;
}

std::uint64_t rank_seed(std::uint64_t seed, int rank) {
    return rank == 0 ? seed : derive_seed(derive_seed(seed, kPurposeRank), std::uint64_t(rank));
}

std::uint64_t rank_share(std::uint64_t total, int rank, int ranks) {
    std::uint64_t r = std::uint64_t(rank), n = std::uint64_t(ranks);
    return total / n + (r < total % n ? 1 : 0);
}

} // namespace smallmlt
