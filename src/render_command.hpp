// `smallmlt render`: load, prepare, render with the path tracer, write files.
#pragma once
#include "cli.hpp"

namespace smallmlt {

int run_render(const RenderOptions& o);
int run_devices();
int run_budget(const BudgetOptions& o);
int run_compare(const std::string& image, const std::string& reference);

} // namespace smallmlt
