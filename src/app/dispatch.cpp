#include "app/commands.hpp"

#include <cstdio>

#ifndef SMALLMLT_VERSION
#define SMALLMLT_VERSION "0.1.0"
#endif

namespace smallmlt {

int run_command(const Command& c, const char* program, RankGroup& ranks) {
    if (c.kind == CommandKind::Render) return run_render(c.render, ranks);
    if (ranks.rank() != 0) return 0; // the other commands run once
    switch (c.kind) {
    case CommandKind::Help:
        std::fputs(usage_text(), stdout);
        return 0;
    case CommandKind::Version:
        std::printf("%s %s\n", program, SMALLMLT_VERSION);
        return 0;
    case CommandKind::Budget:
        return run_budget(c.budget);
    case CommandKind::Compare:
        return run_compare(c.image, c.reference, c.mask);
    case CommandKind::Devices:
        return run_devices();
    case CommandKind::Render:
        break;
    }
    return 0;
}

} // namespace smallmlt
