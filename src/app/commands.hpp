// The commands of `smallmlt`, one file each; main.cpp dispatches to them.
// Each returns the process's exit status or throws (base/error.hpp).
#pragma once
#include "app/cli.hpp"

#include <string>

namespace smallmlt {

int run_render(const RenderOptions& o);   // render_command.cpp
int run_budget(const BudgetOptions& o);   // budget_command.cpp
int run_compare(const std::string& image, // compare_command.cpp
                const std::string& reference);
int run_devices(); // devices_command.cpp

} // namespace smallmlt
