// smallmlt entry point: dispatches commands and turns errors into messages
// and exit codes (src/error.hpp).
#include "app/cli.hpp"
#include "app/commands.hpp"
#include "base/error.hpp"

#include <cstdio>
#include <exception>

#ifndef SMALLMLT_VERSION
#define SMALLMLT_VERSION "0.1.0"
#endif

int main(int argc, char** argv) {
    using namespace smallmlt;
    try {
        Command c = parse_command_line(argc, argv);
        switch (c.kind) {
        case CommandKind::Help:
            std::fputs(usage_text(), stdout);
            return 0;
        case CommandKind::Version:
            std::printf("smallmlt %s\n", SMALLMLT_VERSION);
            return 0;
        case CommandKind::Budget:
            return run_budget(c.budget);
        case CommandKind::Compare:
            return run_compare(c.image, c.reference);
        case CommandKind::Devices:
            return run_devices();
        case CommandKind::Render: {
            SingleRank one;
            return run_render(c.render, one);
        }
        }
    } catch (const UsageError& e) {
        std::fprintf(stderr, "smallmlt: %s\n", e.what());
        return kExitUsageError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "smallmlt: %s\n", e.what());
        return kExitInputError;
    }
    return 0;
}
