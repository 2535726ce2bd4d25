// The ranks of an MPI job (Open MPI) as a RankGroup: each collective of a
// render is one MPI call on MPI_COMM_WORLD.
#pragma once
#include "render/ranks.hpp"

#include <mpi.h>

namespace smallmlt {

class MpiRanks : public RankGroup {
  public:
    MpiRanks();
    int rank() const override { return rank_; }
    int size() const override { return size_; }
    int local_rank() const override { return local_rank_; }
    std::string host() const override { return host_; }
    bool any(bool mine) override;
    bool all(bool mine) override;
    void sum_to_root(std::vector<std::uint64_t>& v) override;
    void sum_to_root(std::vector<double>& v) override;
    void sum_all(std::vector<double>& v) override;
    std::vector<std::string> gather(const std::string& mine) override;

  private:
    int rank_ = 0, size_ = 1, local_rank_ = 0;
    std::string host_;
};

} // namespace smallmlt
