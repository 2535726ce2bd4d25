// The command line: the command, its arguments, and the rules that take
// more than one flag (--spp or --time, --log needs --reference).
#include "app/cli.hpp"

#include "base/error.hpp"

#include <optional>
#include <string>
#include <vector>

namespace smallmlt {

namespace {

struct ArgReader {
    int argc;
    const char* const* argv;
    int i;

    bool done() const { return i >= argc; }
    std::string next() { return argv[i++]; }
    // Value of `flag`, given as "--flag value" or "--flag=value".
    std::string value(const std::string& flag, const std::string& arg) {
        std::size_t eq = arg.find('=');
        if (eq != std::string::npos) return arg.substr(eq + 1);
        if (done()) throw UsageError(flag + ": missing value");
        return next();
    }
};

// What is not a known option: an unknown option is an error, the first
// other argument is the scene, a second one is an error.
void take_scene(const std::string& arg, const std::string& flag, std::string& scene) {
    if (arg.rfind("-", 0) == 0)
        throw UsageError("unknown option " + flag + " (see smallmlt --help)");
    if (!scene.empty()) throw UsageError("unexpected argument '" + arg + "': one scene at a time");
    scene = arg;
}

std::string default_out(const std::string& scene) {
    std::size_t slash = scene.find_last_of('/');
    std::string base = scene.substr(slash == std::string::npos ? 0 : slash + 1);
    std::size_t dot = base.find_last_of('.');
    return (dot == std::string::npos ? base : base.substr(0, dot)) + ".png";
}

// The flags of the table that Options' command takes, and its scene; the
// flags given, in order.
template <class Options> std::vector<const Flag*> parse_flags(ArgReader& r, Options& o) {
    std::vector<const Flag*> given;
    while (!r.done()) {
        std::string arg = r.next();
        std::string name = arg.substr(0, arg.find('='));
        const Flag* f = find_flag(name);
        if (!f || !takes(*f, o) || (!*f->syntax && arg != name)) {
            take_scene(arg, name, o.scene);
            continue;
        }
        apply(*f, o, FlagValue{*f, *f->syntax ? r.value(name, arg) : ""});
        given.push_back(f);
    }
    return given;
}

// The flags of the other method's section: PT's with MLT, MLT's with PT.
std::vector<std::string> idle_flag_warnings(const std::vector<const Flag*>& given, Method m) {
    const Section idle = m == Method::Pt ? Section::Mlt : Section::Pt;
    std::vector<std::string> w;
    for (const Flag* f : given)
        if (f->section == idle)
            w.push_back("warning: " + std::string(f->name) + " changes nothing with --method " +
                        (m == Method::Pt ? "pt" : "mlt") + " (ignored)");
    return w;
}

// --mutations-per-sample weighs Kelemen's weights: with expected values
// alone it changes nothing.
std::optional<std::string> weights_flag_warning(const std::vector<const Flag*>& given,
                                                const RenderOptions& o) {
    if (o.method != Method::Mlt || o.mlt.kelemen) return std::nullopt;
    for (const Flag* f : given)
        if (std::string(f->name) == "--mutations-per-sample")
            return "warning: --mutations-per-sample changes nothing with --weights expected "
                   "(ignored)";
    return std::nullopt;
}

RenderOptions parse_render(ArgReader& r) {
    RenderOptions o;
    const std::vector<const Flag*> given = parse_flags(r, o);
    o.warnings = idle_flag_warnings(given, o.method);
    if (const auto w = weights_flag_warning(given, o)) o.warnings.push_back(*w);
    if (o.scene.empty()) throw UsageError("render: no scene file given");
    if (o.spp && o.time_s) throw UsageError("--spp and --time: give one of them, not both");
    if (!o.spp && !o.time_s) o.spp = kDefaultSpp;
    if (o.outs.empty()) o.outs.push_back(default_out(o.scene));
    if (!o.log.empty() && o.reference.empty())
        throw UsageError("--log " + o.log + ": give --reference, the image to measure against");
    if (!o.reference_mask.empty() && o.reference.empty())
        throw UsageError("--reference-mask " + o.reference_mask +
                         ": give --reference, the image to measure against");
    return o;
}

BudgetOptions parse_budget(ArgReader& r) {
    BudgetOptions o;
    parse_flags(r, o);
    if (o.scene.empty()) throw UsageError("budget: no scene file given");
    return o;
}

} // namespace

Command parse_command_line(int argc, const char* const* argv) {
    ArgReader r{argc, argv, 1};
    Command c;
    if (r.done()) throw UsageError("no command given (see smallmlt --help)");
    std::string cmd = r.next();
    const bool command = cmd == "render" || cmd == "budget" || cmd == "compare" || cmd == "devices";
    for (int i = r.i; i < argc && command; ++i)
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") return c;
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
        c.kind = CommandKind::Help;
    } else if (cmd == "--version") {
        c.kind = CommandKind::Version;
    } else if (cmd == "devices") {
        c.kind = CommandKind::Devices;
        if (!r.done()) throw UsageError("devices: unexpected argument '" + r.next() + "'");
    } else if (cmd == "budget") {
        c.kind = CommandKind::Budget;
        c.budget = parse_budget(r);
    } else if (cmd == "compare") {
        c.kind = CommandKind::Compare;
        std::vector<std::string> files; // IMAGE REFERENCE, with --mask FILE anywhere
        while (!r.done()) {
            std::string arg = r.next();
            std::string flag = arg.substr(0, arg.find('='));
            if (flag == "--mask")
                c.mask = r.value(flag, arg);
            else if (arg.rfind("-", 0) == 0)
                throw UsageError("unknown option " + flag + " (see smallmlt --help)");
            else
                files.push_back(arg);
        }
        if (files.size() < 2) throw UsageError("compare: give IMAGE and REFERENCE");
        if (files.size() > 2) throw UsageError("compare: unexpected argument '" + files[2] + "'");
        c.image = files[0];
        c.reference = files[1];
    } else if (cmd == "render") {
        c.kind = CommandKind::Render;
        c.render = parse_render(r);
    } else {
        throw UsageError("unknown command '" + cmd +
                         "' (expected render, budget, compare or devices; see --help)");
    }
    return c;
}

} // namespace smallmlt
