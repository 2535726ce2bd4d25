#include "mpi/mpi_ranks.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace smallmlt {

namespace {

void check(int err, const char* what) {
    if (err == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int n = 0;
    MPI_Error_string(err, text, &n);
    throw std::runtime_error(std::string(what) + " failed: " + std::string(text, std::size_t(n)));
}

// MPI counts are ints: long vectors go in pieces.
constexpr std::size_t kChunk = std::size_t(1) << 28;

template <typename T> void reduce_sum(std::vector<T>& v, MPI_Datatype type, int rank) {
    for (std::size_t at = 0; at < v.size(); at += kChunk) {
        int n = int(std::min(kChunk, v.size() - at));
        void* data = v.data() + at;
        check(
            MPI_Reduce(rank == 0 ? MPI_IN_PLACE : data, data, n, type, MPI_SUM, 0, MPI_COMM_WORLD),
            "MPI_Reduce");
    }
}

} // namespace

MpiRanks::MpiRanks() {
    check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
    MPI_Comm local;
    check(MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &local),
          "MPI_Comm_split_type");
    check(MPI_Comm_rank(local, &local_rank_), "MPI_Comm_rank");
    MPI_Comm_free(&local);
    char name[MPI_MAX_PROCESSOR_NAME];
    int n = 0;
    check(MPI_Get_processor_name(name, &n), "MPI_Get_processor_name");
    host_.assign(name, std::size_t(n));
}

bool MpiRanks::any(bool mine) {
    int in = mine, out = 0;
    check(MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD), "MPI_Allreduce");
    return out != 0;
}

bool MpiRanks::all(bool mine) {
    int in = mine, out = 0;
    check(MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD), "MPI_Allreduce");
    return out != 0;
}

void MpiRanks::sum_to_root(std::vector<std::uint64_t>& v) {
    reduce_sum(v, MPI_UINT64_T, rank_);
}

void MpiRanks::sum_to_root(std::vector<double>& v) {
    reduce_sum(v, MPI_DOUBLE, rank_);
}

void MpiRanks::sum_all(std::vector<double>& v) {
    // Rank 0's sums, broadcast: every rank gets the same bits.
    reduce_sum(v, MPI_DOUBLE, rank_);
    for (std::size_t at = 0; at < v.size(); at += kChunk) {
        int n = int(std::min(kChunk, v.size() - at));
        check(MPI_Bcast(v.data() + at, n, MPI_DOUBLE, 0, MPI_COMM_WORLD), "MPI_Bcast");
    }
}

std::vector<std::string> MpiRanks::gather(const std::string& mine) {
    int len = int(std::min<std::size_t>(mine.size(), INT_MAX));
    std::vector<int> lens(rank_ == 0 ? std::size_t(size_) : 0);
    check(MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
    std::vector<int> at(lens.size(), 0);
    int total = 0;
    for (std::size_t k = 0; k < lens.size(); ++k) {
        at[k] = total;
        total += lens[k];
    }
    std::string all(std::size_t(total), '\0');
    check(MPI_Gatherv(mine.data(), len, MPI_CHAR, all.data(), lens.data(), at.data(), MPI_CHAR, 0,
                      MPI_COMM_WORLD),
          "MPI_Gatherv");
    std::vector<std::string> out;
    for (std::size_t k = 0; k < lens.size(); ++k)
        out.push_back(all.substr(std::size_t(at[k]), std::size_t(lens[k])));
    return out;
}

} // namespace smallmlt
