// smallmlt-mpi: `mpirun -np R smallmlt-mpi render SCENE ...` renders one
// image with R ranks, each on its own device (src/render/ranks.hpp); rank 0
// writes the outputs. Other commands run on rank 0 alone. Errors become
// messages naming the rank and host, and exit codes as in smallmlt; an
// error after the ranks have started rendering aborts the whole job.
#include "app/cli.hpp"
#include "app/commands.hpp"
#include "base/error.hpp"
#include "mpi/mpi_ranks.hpp"

#include <cstdio>
#include <exception>

#if defined(__SANITIZE_ADDRESS__)
// In the sanitizer build (make SAN=1): Open MPI's plugins, loaded and
// unloaded at run time, leave allocations that LeakSanitizer reports from
// modules it can no longer name, so leak checks are off in smallmlt-mpi;
// address and undefined-behaviour checks stay on, and smallmlt keeps them all.
extern "C" const char* __asan_default_options() {
    return "detect_leaks=0";
}
#endif

namespace {

int run(int argc, char** argv, smallmlt::MpiRanks& ranks) {
    using namespace smallmlt;
    Command c = parse_command_line(argc, argv); // the same on every rank
    if (c.kind == CommandKind::Render) return run_command(c, "smallmlt-mpi", ranks);
    try {
        return run_command(c, "smallmlt-mpi", ranks); // on rank 0 alone
    } catch (const UsageError& e) {
        std::fprintf(stderr, "smallmlt-mpi: %s\n", e.what());
        return kExitUsageError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "smallmlt-mpi: %s\n", e.what());
        return kExitInputError;
    }
}

} // namespace

int main(int argc, char** argv) {
    using namespace smallmlt;
    MPI_Init(&argc, &argv);
    int code = 0;
    {
        MpiRanks ranks;
        // The command line is the same on every rank: rank 0 reports it. A
        // render that cannot start on some rank is reported by every rank
        // (RankFailure); a failure while rendering aborts the job, so that
        // no rank waits for the one that failed.
        try {
            code = run(argc, argv, ranks);
        } catch (const UsageError& e) {
            if (ranks.rank() == 0 || ranks.size() == 1)
                std::fprintf(stderr, "smallmlt-mpi: %s\n", e.what());
            code = kExitUsageError;
        } catch (const RankFailure& e) {
            std::fprintf(stderr, "smallmlt-mpi: %s\n", e.what());
            code = e.exit_code;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "smallmlt-mpi: rank %d on %s: %s\n", ranks.rank(),
                         ranks.host().c_str(), e.what());
            MPI_Abort(MPI_COMM_WORLD, kExitInputError);
        }
    }
    MPI_Finalize();
    return code;
}
