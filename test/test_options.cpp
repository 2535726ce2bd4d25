// The table of options (src/app/options.hpp): the library's defaults are
// what an empty command line gives, render and budget read their shared
// flags alike, every flag is in --help, and bad values are errors naming
// the flag. No device is needed.
#include "app/cli.hpp"
#include "base/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include <vector>

using namespace smallmlt;

namespace {

// `line` split at spaces, after the program's name.
Command parse(const std::string& line) {
    std::vector<std::string> words = {"smallmlt"};
    for (std::size_t at = 0; at <= line.size();) {
        std::size_t end = std::min(line.find(' ', at), line.size());
        if (end > at) words.push_back(line.substr(at, end - at));
        at = end + 1;
    }
    std::vector<const char*> argv;
    for (const std::string& w : words)
        argv.push_back(w.c_str());
    return parse_command_line(int(argv.size()), argv.data());
}

// The UsageError of `line`, or "" if it parses.
std::string usage_error(const std::string& line) {
    try {
        parse(line);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

bool is_choice(const Flag& f) {
    std::string s = f.syntax;
    return s.find('|') != std::string::npos && s != "N|auto";
}

// The command that takes f ("render", or "budget" for its own flags).
std::string command_of(const Flag& f) {
    return takes(f, RenderOptions()) ? "render s.scene " : "budget s.scene ";
}

} // namespace

// MltOptions{} is the renderer `render SCENE` runs, field by field; only
// threads and max_alloc_bytes are fitted to the device (make_integrator),
// and seed is RenderOptions::seed, made per rank.
TEST(Options, EmptyCommandLineGivesTheLibraryDefaults) {
    const RenderOptions o = parse("render s.scene").render;
    const MltOptions lib, &m = o.mlt;
    EXPECT_EQ(m.proposals, lib.proposals);
    EXPECT_EQ(m.large_step, lib.large_step);
    EXPECT_EQ(large_step_of(m), large_step_of(lib));
    EXPECT_EQ(o.seed, lib.seed);
    EXPECT_EQ(m.seed, lib.seed);
    EXPECT_EQ(m.burn_in, lib.burn_in);
    EXPECT_EQ(m.burn_in_iters, lib.burn_in_iters);
    EXPECT_EQ(m.film_atomics64, lib.film_atomics64);
    EXPECT_EQ(m.max_alloc_bytes, lib.max_alloc_bytes);
    EXPECT_EQ(m.film_pass_mutations, lib.film_pass_mutations);
    EXPECT_EQ(m.stuck_run, lib.stuck_run);
    EXPECT_EQ(m.split, lib.split);
    EXPECT_EQ(m.omc_effort, lib.omc_effort);
    EXPECT_EQ(m.omc_cells, lib.omc_cells);
    EXPECT_EQ(m.target, lib.target);
    EXPECT_EQ(m.kelemen, lib.kelemen);
    EXPECT_EQ(m.mutations_per_sample, lib.mutations_per_sample);
    EXPECT_EQ(m.strata, lib.strata);
    EXPECT_EQ(m.film_step, lib.film_step);
    EXPECT_EQ(m.path_step, lib.path_step);
    EXPECT_EQ(m.restart, lib.restart);
    EXPECT_FALSE(o.threads) << "--threads auto";
    // Path tracing: PathTracer's default sampler, and the roulette of Scene.
    EXPECT_EQ(o.sampler, kDefaultPtSampler);
    const Roulette rr;
    EXPECT_EQ(o.roulette.start, rr.start);
    EXPECT_EQ(o.roulette.threshold, rr.threshold);
    EXPECT_EQ(o.roulette.cap, rr.cap);
    EXPECT_EQ(o.roulette.by_luminance, rr.by_luminance);
    EXPECT_EQ(o.spp, kDefaultSpp);
    // Budget's chains are render's.
    const MltOptions& b = parse("budget s.scene").budget.mlt;
    EXPECT_EQ(b.proposals, lib.proposals);
    EXPECT_EQ(b.split, lib.split);
    EXPECT_EQ(b.omc_cells, lib.omc_cells);
    EXPECT_EQ(b.target, lib.target);
}

// The large step's default follows burn-in and the weights, on the command
// line as in the library, and a given one is kept.
TEST(Options, LargeStepDefaultDependsOnBurnInAndWeightsAlike) {
    struct Case {
        const char* flags;
        bool burn_in, kelemen;
    } cases[] = {{"", true, true},
                 {" --weights expected", true, false},
                 {" --burn-in none", false, true},
                 {" --burn-in none --weights expected", false, false}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.flags);
        MltOptions lib;
        lib.burn_in = c.burn_in;
        lib.kelemen = c.kelemen;
        const MltOptions m = parse(std::string("render s.scene") + c.flags).render.mlt;
        EXPECT_EQ(m.burn_in, c.burn_in);
        EXPECT_EQ(m.kelemen, c.kelemen);
        EXPECT_FALSE(m.large_step);
        EXPECT_EQ(large_step_of(m), large_step_of(lib));
        EXPECT_EQ(large_step_of(m), default_large_step(c.burn_in, c.kelemen));
    }
    EXPECT_EQ(large_step_of(parse("render s.scene --large-step 0.25").render.mlt), 0.25f);
    // Restarts lower it where their samples are large steps' (burn-in,
    // Kelemen's weights); auto only once resolved to steps.
    EXPECT_EQ(large_step_of(parse("render s.scene --restart 16").render.mlt),
              kDefaultLargeStepRestart);
    EXPECT_EQ(large_step_of(parse("render s.scene --restart auto").render.mlt),
              kDefaultLargeStepKelemen);
    EXPECT_EQ(large_step_of(parse("render s.scene --restart 16 --weights expected").render.mlt),
              kDefaultLargeStepBurnIn);
    EXPECT_EQ(large_step_of(parse("render s.scene --restart 16 --large-step 0.25").render.mlt),
              0.25f);
}

// A flag render and budget share is one entry and sets the same fields.
TEST(Options, BudgetReadsTheSharedFlagsAsRenderDoes) {
    const std::string flags = " --threads 512 --proposals 4 --split direct --omc-cells off "
                              "--target two-stage "
                              "--depth 0 --width 8 --height 9 --device-mem 64M "
                              "--profile adreno-650 --device 1";
    const RenderOptions r = parse("render s.scene" + flags).render;
    const BudgetOptions b = parse("budget s.scene" + flags).budget;
    const JobOptions* both[] = {&r, &b};
    for (const JobOptions* o : both) {
        EXPECT_EQ(o->threads, 512u);
        EXPECT_EQ(o->mlt.proposals, 4u);
        EXPECT_EQ(o->mlt.split, Split::Direct);
        EXPECT_FALSE(o->mlt.omc_cells);
        EXPECT_TRUE(MltOptions().omc_cells) << "the flag must change the default";
        EXPECT_EQ(o->mlt.target, Target::TwoStage);
        EXPECT_EQ(o->depth, 0);
        EXPECT_EQ(o->width, 8);
        EXPECT_EQ(o->height, 9);
        EXPECT_EQ(o->device_mem, 64u << 20);
        EXPECT_EQ(o->profile, "adreno-650");
        EXPECT_EQ(o->device, 1);
    }
    std::set<std::string> names;
    for (const Flag& f : flag_table())
        EXPECT_TRUE(names.insert(f.name).second) << f.name << " is declared twice";
    EXPECT_EQ(usage_error("budget s.scene --spp 2"), "unknown option --spp (see smallmlt --help)");
    EXPECT_EQ(usage_error("render s.scene --format csv"),
              "unknown option --format (see smallmlt --help)");
}

// --depth is the scene's maximum bounce depth for both commands: 0..64.
TEST(Options, DepthIsZeroTo64ForRenderAndBudget) {
    for (const char* cmd : {"render", "budget"}) {
        std::string line = std::string(cmd) + " s.scene --depth ";
        EXPECT_EQ(usage_error(line + "0"), "") << cmd;
        EXPECT_EQ(usage_error(line + "64"), "") << cmd;
        EXPECT_EQ(usage_error(line + "-1"), "--depth: -1 is out of range 0..64") << cmd;
        EXPECT_EQ(usage_error(line + "65"), "--depth: 65 is out of range 0..64") << cmd;
    }
    EXPECT_EQ(parse("budget s.scene --depth 64").budget.depth, 64);
}

// --help shows every flag of the table, each in its place, and budget names
// the flags it shares with render.
TEST(Options, HelpListsEveryFlagOfTheTable) {
    const std::string help = usage_text();
    const std::size_t budget = help.find("\nBudget options:\n");
    ASSERT_NE(budget, std::string::npos);
    std::set<std::string> shared; // the words after "as for render:"
    std::string word;
    for (char c : help.substr(help.find("as for render:", budget)) + " ") {
        if (c != ' ' && c != ',' && c != '\n') {
            word += c;
            continue;
        }
        if (!word.empty()) shared.insert(word);
        word.clear();
    }
    for (const Flag& f : flag_table()) {
        std::string line = std::string("\n  ") + f.name + (*f.syntax ? " " : "") + f.syntax + " ";
        EXPECT_NE(help.find(line), std::string::npos) << f.name << " is not in --help";
        EXPECT_EQ(help.find(f.name) < budget, takes(f, RenderOptions()))
            << f.name << " is in the wrong part of --help";
        const bool both = takes(f, RenderOptions()) && takes(f, BudgetOptions());
        EXPECT_EQ(shared.count(f.name), both ? 1u : 0u) << f.name << " among budget's flags";
        EXPECT_EQ(flag_help(f).find('{'), std::string::npos) << f.name << ": " << flag_help(f);
    }
    EXPECT_NE(help.find("maximum bounces, 0..64"), std::string::npos);
    EXPECT_EQ(flag_help(*find_flag("--large-step")),
              "probability that a mutation draws a whole new path (default 0.3 with burn-in, 0.1 "
              "with burn-in and restarts, 0.1 with burn-in and --weights expected, 0.5 without "
              "burn-in)");
}

// Every alternative a choice's syntax shows is one its setter takes.
TEST(Options, EveryChoiceOfTheSyntaxParses) {
    int choices = 0;
    for (const Flag& f : flag_table()) {
        if (!is_choice(f)) continue;
        ++choices;
        for (const std::string& a : flag_choices(f)) {
            // A placeholder among the words ("PIXELS") stands for a number.
            const bool number =
                std::all_of(a.begin(), a.end(), [](char c) { return std::isupper(c); });
            const std::string arg = number ? "8" : a;
            EXPECT_NO_THROW(parse(command_of(f) + f.name + " " + arg)) << f.name << " " << arg;
        }
    }
    EXPECT_GE(choices, 9);
}

TEST(Options, ChoicesSetTheirFields) {
    EXPECT_EQ(parse("render s.scene --method pt").render.method, Method::Pt);
    EXPECT_EQ(parse("render s.scene --method mlt").render.method, Method::Mlt);
    EXPECT_FALSE(parse("render s.scene --weights expected").render.mlt.kelemen);
    EXPECT_TRUE(parse("render s.scene --weights kelemen").render.mlt.kelemen);
    EXPECT_FALSE(parse("render s.scene --burn-in none").render.mlt.burn_in);
    EXPECT_EQ(parse("render s.scene --restart 32").render.mlt.restart, 32u);
    EXPECT_EQ(parse("render s.scene --restart auto").render.mlt.restart, kRestartAuto);
    EXPECT_EQ(parse("render s.scene --path-step 64").render.mlt.path_step, 64u);
    EXPECT_EQ(parse("render s.scene --mutations-per-sample 1").render.mlt.mutations_per_sample,
              std::optional<double>(1.0));
    EXPECT_EQ(usage_error("render s.scene --mutations-per-sample 0"),
              "--mutations-per-sample: '0' is not a positive number of mutations");
    EXPECT_EQ(usage_error("render s.scene --path-step 100"),
              "--path-step: 100 is not a power of two");
    EXPECT_TRUE(parse("render s.scene --burn-in omc").render.mlt.burn_in);
    EXPECT_TRUE(parse("render s.scene --film-atomics 64").render.mlt.film_atomics64);
    EXPECT_FALSE(parse("render s.scene --film-atomics 32").render.mlt.film_atomics64);
    EXPECT_TRUE(parse("render s.scene --rr-by luminance").render.roulette.by_luminance);
    EXPECT_EQ(parse("render s.scene --sampler random").render.sampler, PtSampler::Random);
    EXPECT_EQ(parse("render s.scene --sampler sobol").render.sampler, PtSampler::Sobol);
    EXPECT_EQ(parse("budget s.scene --format csv").budget.format, BudgetFormat::Csv);
    EXPECT_EQ(parse("budget s.scene --format json").budget.format, BudgetFormat::Json);
    EXPECT_EQ(parse("budget s.scene --format table").budget.format, BudgetFormat::Table);
    EXPECT_EQ(usage_error("render s.scene --weights veach"),
              "--weights: 'veach' is not a weighting (expected or kelemen)");
    EXPECT_EQ(usage_error("budget s.scene --format xml"),
              "--format: 'xml' is not a format (table, csv or json)");
}

// A flag of the other method's section is a warning, whatever the order:
// MLT's with PT, PT's with MLT; the method's own flags are none.
TEST(Options, OtherMethodsFlagsWarn) {
    EXPECT_EQ(parse("render s.scene --film-step 8 --path-step 64 --sampler sobol --method pt")
                  .render.warnings,
              (std::vector<std::string>{
                  "warning: --film-step changes nothing with --method pt (ignored)",
                  "warning: --path-step changes nothing with --method pt (ignored)"}));
    EXPECT_EQ(
        parse("render s.scene --sampler random --film-step 8").render.warnings,
        std::vector<std::string>{"warning: --sampler changes nothing with --method mlt (ignored)"});
    EXPECT_TRUE(
        parse("render s.scene --method pt --sampler random --spp 2").render.warnings.empty());
    EXPECT_TRUE(parse("render s.scene --path-step 64 --threads 64").render.warnings.empty());
}

// --mutations-per-sample weighs Kelemen's weights: with expected values
// alone it changes nothing, and says so.
TEST(Options, MutationsPerSampleWarnsWithExpectedValues) {
    EXPECT_EQ(parse("render s.scene --weights expected --mutations-per-sample 2").render.warnings,
              std::vector<std::string>{"warning: --mutations-per-sample changes nothing with "
                                       "--weights expected (ignored)"});
    EXPECT_TRUE(parse("render s.scene --mutations-per-sample 2").render.warnings.empty());
    EXPECT_TRUE(parse("render s.scene --weights expected").render.warnings.empty());
}

// A missing or bad value is a UsageError that starts with the flag's name.
TEST(Options, ErrorsNameTheFlag) {
    for (const Flag& f : flag_table()) {
        const std::string line = command_of(f) + f.name;
        if (!*f.syntax) {
            EXPECT_EQ(usage_error(line), "") << line;
            EXPECT_NE(usage_error(line + "=1"), "") << line;
            continue;
        }
        EXPECT_EQ(usage_error(line), std::string(f.name) + ": missing value");
        const std::string bad = usage_error(line + " @");
        EXPECT_EQ(bad.rfind(f.name, 0), 0u) << line << " @: " << bad;
        EXPECT_EQ(usage_error(line + "=@"), bad) << line;
    }
}
