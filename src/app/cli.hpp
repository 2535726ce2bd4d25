// Command-line parsing. Bad flags and values throw UsageError naming the
// flag. The flags of render and budget are the table of options.hpp.
#pragma once
#include "app/options.hpp"

#include <string>

namespace smallmlt {

enum class CommandKind { Render, Budget, Compare, Devices, Help, Version };

struct Command {
    CommandKind kind = CommandKind::Help;
    RenderOptions render;
    BudgetOptions budget;
    std::string image, reference; // compare
    std::string mask;             // compare --mask
};

Command parse_command_line(int argc, const char* const* argv);

// --help (usage.cpp).
const char* usage_text();

} // namespace smallmlt
