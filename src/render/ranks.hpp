// The processes (ranks) that render one image together: one rank in
// `smallmlt`, R ranks under MPI in `smallmlt-mpi` (src/mpi/). Each rank runs
// its own method on its own device with its own share of the work; the
// ranks agree once per pass on whether to stop, and their tallies (exact
// integer film sums, sample counts) are summed into rank 0's image. The
// collectives here are all a render needs, so the render code does not
// depend on MPI.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace smallmlt {

class RankGroup {
  public:
    virtual ~RankGroup() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    virtual int local_rank() const = 0; // among the ranks on this host
    virtual std::string host() const = 0;
    // Collectives: every rank calls them in the same order.
    virtual bool any(bool mine) = 0; // true if true on some rank
    virtual bool all(bool mine) = 0; // true if true on every rank
    // Element-wise sums over ranks into rank 0's vectors (same length on
    // every rank; others' are left as they were).
    virtual void sum_to_root(std::vector<std::uint64_t>& v) = 0;
    virtual void sum_to_root(std::vector<double>& v) = 0;
    // Element-wise sums over ranks into every rank's vector.
    virtual void sum_all(std::vector<double>& v) = 0;
    // Each rank's text, in rank order, on rank 0 (empty elsewhere).
    virtual std::vector<std::string> gather(const std::string& mine) = 0;
};

// A render that could not start on every rank: every rank throws it, after
// the ranks have agreed, with a message naming the rank and its host (and
// on rank 0 every rank that failed), and the exit status to return.
struct RankFailure : std::runtime_error {
    RankFailure(const std::string& what, int exit_code)
        : std::runtime_error(what), exit_code(exit_code) {}
    int exit_code;
};

// The one rank of a single process.
class SingleRank : public RankGroup {
  public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    int local_rank() const override { return 0; }
    std::string host() const override;
    bool any(bool mine) override { return mine; }
    bool all(bool mine) override { return mine; }
    void sum_to_root(std::vector<std::uint64_t>&) override {}
    void sum_to_root(std::vector<double>&) override {}
    void sum_all(std::vector<double>&) override {}
    std::vector<std::string> gather(const std::string& mine) override { return {mine}; }
};

// What rank `rank` of `ranks` renders: MLT chains of their own seed (rank 0
// keeps the render's, so one rank renders what `smallmlt` does), PT samples
// rank, rank + ranks, rank + 2 ranks, ... of every pixel.
std::uint64_t rank_seed(std::uint64_t seed, int rank);

// A rank's share of `total` units of work divided evenly (the first
// total % ranks ranks do one more).
std::uint64_t rank_share(std::uint64_t total, int rank, int ranks);

} // namespace smallmlt
