// The commands of `smallmlt`, one file each; main.cpp dispatches to them.
// Each returns the process's exit status or throws (base/error.hpp).
#pragma once
#include "app/cli.hpp"
#include "device/ocl.hpp"
#include "render/integrator.hpp"
#include "render/ranks.hpp"
#include "scene/device_scene.hpp"

#include <memory>
#include <string>

namespace smallmlt {

// dispatch.cpp: runs command c of `program` (smallmlt or smallmlt-mpi):
// render on every rank, the others on rank 0 alone.
int run_command(const Command& c, const char* program, RankGroup& ranks);

// render_command.cpp: `ranks` render one image together (one in smallmlt).
int run_render(const RenderOptions& o, RankGroup& ranks);
// The method rank ranks.rank() of ranks.size() runs for `o` on `cl`, sized
// to the device (what run_render runs; tests rebuild a job's ranks with it).
std::unique_ptr<Integrator> make_integrator(const RenderOptions& o, const ClContext& cl,
                                            const DeviceScene& ds, const RankGroup& ranks);
// Prints the scene's warnings on stderr, one a line, as "smallmlt: ..."
// (render_command.cpp).
void print_scene_warnings(const Scene& scene);

// Halves the scene's textures to fit the device (texture_budget) and
// --texture-max; returns what it halved, for a note ("" if nothing).
std::string fit_scene_textures(Scene& scene, const DeviceBudget& budget,
                               std::optional<int> texture_max);
int run_budget(const BudgetOptions& o);   // budget_command.cpp
int run_compare(const std::string& image, // compare_command.cpp
                const std::string& reference, const std::string& mask);
int run_devices(); // devices_command.cpp

} // namespace smallmlt
