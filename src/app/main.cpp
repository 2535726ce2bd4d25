// smallmlt entry point: dispatches commands and turns errors into messages
// and exit codes (src/base/error.hpp).
#include "app/cli.hpp"
#include "app/commands.hpp"
#include "base/error.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    using namespace smallmlt;
    try {
        SingleRank one;
        return run_command(parse_command_line(argc, argv), "smallmlt", one);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "smallmlt: %s\n", e.what());
        return kExitUsageError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "smallmlt: %s\n", e.what());
        return kExitInputError;
    }
    return 0;
}
