// Command-line parsing. Bad flags and values throw UsageError naming the flag.
#pragma once
#include "render/mlt.hpp"
#include "render/path_tracer.hpp"
#include "scene/sample_layout.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace smallmlt {

constexpr std::uint32_t kDefaultSpp = 16;

enum class Method { Pt, Mlt };

struct RenderOptions {
    std::string scene;
    Method method = Method::Mlt;
    std::optional<float> large_step;      // default depends on burn-in
    std::optional<std::uint32_t> threads; // unset: auto (src/memory_plan.hpp)
    std::uint32_t proposals = 1;          // K: threads per chain
    std::optional<std::uint64_t> device_mem;
    std::optional<std::string> profile; // --profile: a device of doc/devices.md
    bool film_atomics64 = false;        // --film-atomics 64
    Split split = kDefaultSplit;        // --split
    Target target = kDefaultTarget;     // --target
    bool kelemen = kDefaultKelemen;     // --weights kelemen
    double omc_effort = 1.0;            // --omc-effort
    bool burn_in = true;
    std::uint32_t burn_in_iters = MltOptions().burn_in_iters;
    std::uint32_t stuck_run = MltOptions().stuck_run;
    std::optional<std::uint32_t> spp;
    std::optional<double> time_s;
    std::uint64_t seed = 1;
    std::vector<std::string> outs;
    std::string reference;       // --reference: error measured against it
    std::string log;             // --log: CSV of error against render time
    double log_interval_s = 1.0; // --log-every
    std::string reference_mask;  // --reference-mask: its lit pixels are left out of mse_unlit
    std::optional<int> width, height, depth;
    Roulette roulette;                    // --rr-*: every method
    PtSampler sampler = PtSampler::Sobol; // --sampler: path tracing
    int device = 0;
    bool device_given = false; // else: device 0, or under MPI the local rank's
    bool quiet = false;
};

enum class CommandKind { Render, Budget, Compare, Devices, Help, Version };

enum class BudgetFormat { Table, Csv, Json };

struct BudgetOptions {
    std::string scene;
    std::optional<std::uint32_t> threads; // unset: auto
    std::uint32_t proposals = 1;
    Split split = kDefaultSplit;
    Target target = kDefaultTarget;
    std::optional<int> depth;
    std::optional<std::uint64_t> device_mem;
    std::optional<std::string> profile;
    std::optional<int> width, height;
    BudgetFormat format = BudgetFormat::Table;
    int device = 0;
};

struct Command {
    CommandKind kind = CommandKind::Help;
    RenderOptions render;
    BudgetOptions budget;
    std::string image, reference; // compare
    std::string mask;             // compare --mask
};

Command parse_command_line(int argc, const char* const* argv);

const char* usage_text();

} // namespace smallmlt
