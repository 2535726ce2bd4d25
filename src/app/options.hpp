// The options of `render` and `budget`, and the one table of their flags
// (options.cpp): each flag's name, value syntax, range, help and the field
// it sets. The parser (cli.cpp) and --help (usage.cpp) both read the table.
// The defaults are those of the structs below, which take the library's
// (MltOptions, Roulette, kDefaultPtSampler): a command line without a flag
// leaves its field as it is.
#pragma once
#include "render/mlt.hpp"
#include "render/path_tracer.hpp"
#include "scene/sample_layout.hpp"

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace smallmlt {

constexpr std::uint32_t kDefaultSpp = 16;

enum class Method { Pt, Mlt };
enum class BudgetFormat { Table, Csv, Json };

// What render and budget share: the scene, its film and depth, the device
// and the chains.
struct JobOptions {
    std::string scene;
    std::optional<int> width, height, depth; // override the scene's
    int device = 0;
    bool device_given = false; // else: device 0, or under MPI the local rank's
    std::optional<std::uint64_t> device_mem;
    std::optional<std::string> profile;   // --profile: a device of doc/devices.md
    std::optional<std::uint32_t> threads; // unset: auto (src/device/memory_plan.hpp)
    std::optional<int> texture_max;       // --texture-max: longest texture side
    // The chains: --proposals, --split, --target and render's MLT flags.
    // threads, seed and max_alloc_bytes are set per device and rank
    // (make_integrator).
    MltOptions mlt;
};

struct RenderOptions : JobOptions {
    Method method = Method::Mlt;
    std::optional<std::uint32_t> spp; // neither it nor --time: kDefaultSpp
    std::optional<double> time_s;
    std::uint64_t seed = 1;
    std::vector<std::string> outs;
    std::string reference;       // --reference: error measured against it
    std::string log;             // --log: CSV of error against render time
    double log_interval_s = 1.0; // --log-every
    std::string reference_mask;  // --reference-mask: its lit pixels are left out of mse_unlit
    Roulette roulette;           // --rr-*: every method
    PtSampler sampler = kDefaultPtSampler;
    bool quiet = false;
    // Flags given that change nothing with this method ("--sampler changes
    // nothing with --method mlt"), for the render to warn of.
    std::vector<std::string> warnings;
};

struct BudgetOptions : JobOptions {
    BudgetFormat format = BudgetFormat::Table;
};

// Where --help lists a flag.
enum class Section { Render, Pt, Mlt, Budget };

struct Flag;

// A flag's value as given, read as its table entry says. Each reading
// throws UsageError naming the flag.
struct FlagValue {
    const Flag& flag;
    std::string text;

    long long integer() const;          // in flag.lo..flag.hi
    std::uint32_t power_of_two() const; // an integer() that is a power of two
    std::uint64_t u64() const;
    std::uint64_t bytes() const; // a size: 65536, 64K, 16M, 1G
    double probability() const;  // in [0, 1]
    double positive(const char* what = "number") const;
    double non_negative() const;
    // Which of the alternatives "a|b|c" of flag.syntax the text is;
    // `alternatives` is how many the setter knows (std::logic_error if the
    // syntax has another number).
    std::size_t choice(std::size_t alternatives) const;
    // values[choice()], in the order of flag.syntax.
    template <class T> T pick(std::initializer_list<T> values) const {
        return values.begin()[choice(values.size())];
    }
};

using SetJob = void (*)(JobOptions&, const FlagValue&);
using SetRender = void (*)(RenderOptions&, const FlagValue&);
using SetBudget = void (*)(BudgetOptions&, const FlagValue&);

// One flag. Which commands take it is the kind of its setter: a JobOptions
// setter (render and budget), a RenderOptions or a BudgetOptions one.
struct Flag {
    const char* name;   // "--depth"
    const char* syntax; // its value in --help: "D", "N|auto", "pt|mlt" (a choice); "" for a switch
    Section section;
    std::variant<SetJob, SetRender, SetBudget> set;
    const char* help;                        // {range}: lo..hi; {default}: default_text()
    long long lo = 0, hi = 0;                // an integer's range
    const char* noun = nullptr;              // what a choice is, for its error ("method")
    std::string (*default_text)() = nullptr; // the default as --help gives it
};

// Every flag of render and budget, each once, in --help's order.
const std::vector<Flag>& flag_table();
// The flag called `name`, or null.
const Flag* find_flag(const std::string& name);

bool takes(const Flag& f, const RenderOptions&);
bool takes(const Flag& f, const BudgetOptions&);
// Sets what `f` sets from `v`; f must be one `o`'s command takes.
void apply(const Flag& f, RenderOptions& o, const FlagValue& v);
void apply(const Flag& f, BudgetOptions& o, const FlagValue& v);

// The alternatives of f's syntax "a|b|c" (one, the syntax, if it has no |).
std::vector<std::string> flag_choices(const Flag& f);
// f's help with {range} and {default} filled in.
std::string flag_help(const Flag& f);

} // namespace smallmlt
