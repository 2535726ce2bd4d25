// Command-line parsing. Bad flags and values throw UsageError naming the flag.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace smallmlt {

enum class Method { Pt, Mlt };

struct RenderOptions {
    std::string scene;
    Method method = Method::Pt;
    float large_step = 0.5f;
    std::uint32_t threads = 1u << 16;
    std::optional<std::uint32_t> spp;
    std::optional<double> time_s;
    std::uint64_t seed = 1;
    std::vector<std::string> outs;
    std::optional<int> width, height, depth;
    int device = 0;
    bool quiet = false;
};

enum class CommandKind { Render, Devices, Help, Version };

struct Command {
    CommandKind kind = CommandKind::Help;
    RenderOptions render;
};

constexpr std::uint32_t kDefaultSpp = 16;

Command parse_command_line(int argc, const char* const* argv);

const char* usage_text();

} // namespace smallmlt
