// Reading a flag's value: numbers, sizes and choices, each checked against
// the flag's entry of the table (options.hpp); errors name the flag.
#include "app/options.hpp"

#include "base/bits.hpp"
#include "base/error.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace smallmlt {

namespace {

std::string name_of(const FlagValue& v) {
    return v.flag.name;
}

// Reads text as a double (inf and nan too); false unless all of it is one.
bool to_double(const std::string& text, double& x) {
    char* end = nullptr;
    x = std::strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0';
}

// "a or b", "a, b or c".
std::string either(const std::vector<std::string>& names) {
    std::string s;
    for (std::size_t i = 0; i < names.size(); ++i)
        s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return s;
}

} // namespace

std::vector<std::string> flag_choices(const Flag& f) {
    std::vector<std::string> out(1);
    for (const char* c = f.syntax; *c; ++c)
        if (*c == '|')
            out.emplace_back();
        else
            out.back() += *c;
    return out;
}

long long FlagValue::integer() const {
    errno = 0;
    char* end = nullptr;
    long long x = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE)
        throw UsageError(name_of(*this) + ": '" + text + "' is not an integer");
    if (x < flag.lo || x > flag.hi)
        throw UsageError(name_of(*this) + ": " + text + " is out of range " +
                         std::to_string(flag.lo) + ".." + std::to_string(flag.hi));
    return x;
}

std::uint32_t FlagValue::power_of_two() const {
    long long x = integer();
    if (!is_power_of_two(std::uint64_t(x)))
        throw UsageError(name_of(*this) + ": " + text + " is not a power of two");
    return std::uint32_t(x);
}

std::uint64_t FlagValue::u64() const {
    errno = 0;
    char* end = nullptr;
    unsigned long long x = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || *end != '\0' || errno == ERANGE)
        throw UsageError(name_of(*this) + ": '" + text + "' is not a non-negative integer");
    return x;
}

std::uint64_t FlagValue::bytes() const {
    char* end = nullptr;
    errno = 0;
    unsigned long long x = std::strtoull(text.c_str(), &end, 10);
    std::uint64_t scale = 1;
    std::string suffix = end ? end : "";
    if (suffix == "K" || suffix == "k")
        scale = 1ull << 10;
    else if (suffix == "M" || suffix == "m")
        scale = 1ull << 20;
    else if (suffix == "G" || suffix == "g")
        scale = 1ull << 30;
    else if (!suffix.empty())
        scale = 0;
    if (text.empty() || text[0] == '-' || end == text.c_str() || scale == 0 || errno == ERANGE ||
        x == 0 || x > (~0ull) / scale)
        throw UsageError(name_of(*this) + ": '" + text +
                         "' is not a size in bytes (e.g. 65536, 64K, 16M, 1G)");
    return x * scale;
}

double FlagValue::probability() const {
    double x = 0;
    if (!to_double(text, x) || !(x >= 0 && x <= 1))
        throw UsageError(name_of(*this) + ": '" + text + "' is not a probability in [0, 1]");
    return x;
}

double FlagValue::positive(const char* what) const {
    double x = 0;
    if (!to_double(text, x) || !std::isfinite(x) || x <= 0)
        throw UsageError(name_of(*this) + ": '" + text + "' is not a positive " + what);
    return x;
}

double FlagValue::non_negative() const {
    double x = 0;
    if (!to_double(text, x) || !std::isfinite(x) || x < 0)
        throw UsageError(name_of(*this) + ": '" + text + "' is not a number >= 0");
    return x;
}

std::size_t FlagValue::choice(std::size_t count) const {
    std::vector<std::string> names = flag_choices(flag);
    if (names.size() != count)
        throw std::logic_error(name_of(*this) + ": its syntax and its setter disagree");
    for (std::size_t i = 0; i < names.size(); ++i)
        if (text == names[i]) return i;
    if (flag.noun)
        throw UsageError(name_of(*this) + ": '" + text + "' is not a " + flag.noun + " (" +
                         either(names) + ")");
    throw UsageError(name_of(*this) + ": '" + text + "' is not " + either(names));
}

} // namespace smallmlt
