// `smallmlt --help`: the commands, then every flag of the table
// (options.hpp) with its help, so that the text cannot drift from the parser.
#include "app/cli.hpp"

#include <cstddef>

namespace smallmlt {

namespace {

constexpr std::size_t kHelpColumn = 21; // where a flag's help starts
constexpr std::size_t kWidth = 80;      // lines end before this column

const char* const kCommands = R"(smallmlt: Metropolis light transport for small OpenCL devices

Usage:
  smallmlt render SCENE [options]   render a .scene or a Mitsuba .xml file
  smallmlt budget SCENE [options]   device memory per bounce depth, without rendering
  smallmlt compare IMAGE REFERENCE [--mask FILE]
                                    error of IMAGE against REFERENCE (.pfm or .exr):
                                    MSE, relative MSE and the MSE of 8x8 and 32x32
                                    block means (block8_mse, block32_mse) on linear
                                    values; with --mask, also
                                    the MSE over the pixels where FILE is black
                                    (mse_unlit)
  smallmlt devices                  list OpenCL devices and their memory
  smallmlt --help | --version
)";

const char* const kExitStatus = R"(
Exit status: 0 success, 1 bad input or device error, 2 bad command line,
3 interrupted (the image so far was written).
The scene format is described in doc/scene-format.md.
)";

void replace(std::string& s, const std::string& what, const std::string& with) {
    std::size_t at = s.find(what);
    if (at != std::string::npos) s.replace(at, what.size(), with);
}

// `left`, then `text` from kHelpColumn on (or two spaces after a longer
// left), its words wrapped before kWidth.
std::string wrapped(const std::string& left, const std::string& text) {
    std::string out, line = left;
    line += left.size() + 1 < kHelpColumn ? std::string(kHelpColumn - left.size(), ' ') : "  ";
    bool empty = true; // no word on this line yet
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find(' ', at);
        if (end == std::string::npos) end = text.size();
        std::string word = text.substr(at, end - at);
        at = end + 1;
        if (!empty && line.size() + 1 + word.size() >= kWidth) {
            out += line + "\n";
            line = std::string(kHelpColumn, ' ');
            empty = true;
        }
        line += (empty ? "" : " ") + word;
        empty = false;
    }
    return out + line + "\n";
}

std::string section(const char* title, Section which) {
    std::string s = std::string("\n") + title + ":\n";
    for (const Flag& f : flag_table())
        if (f.section == which)
            s += wrapped(std::string("  ") + f.name + (*f.syntax ? " " : "") + f.syntax,
                         flag_help(f));
    return s;
}

// Budget's own flags, then those it shares with render.
std::string budget_section() {
    std::string shared;
    for (const Flag& f : flag_table())
        if (takes(f, BudgetOptions()) && takes(f, RenderOptions()))
            shared += (shared.empty() ? "" : ", ") + std::string(f.name);
    return section("Budget options", Section::Budget) + wrapped("  as for render:", shared);
}

std::string make_usage() {
    return kCommands + section("Render options", Section::Render) +
           section("PT options", Section::Pt) + section("MLT options", Section::Mlt) +
           budget_section() + kExitStatus;
}

} // namespace

std::string flag_help(const Flag& f) {
    std::string s = f.help;
    replace(s, "{range}", std::to_string(f.lo) + ".." + std::to_string(f.hi));
    if (f.default_text) replace(s, "{default}", f.default_text());
    return s;
}

const char* usage_text() {
    static const std::string text = make_usage();
    return text.c_str();
}

} // namespace smallmlt
