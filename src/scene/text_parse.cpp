#include "scene/text_parse.hpp"

#include "base/error.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace smallmlt {

std::vector<std::string> split_tokens(const std::string& line) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : line) {
        if (c == '#') break;
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f') {
            if (!cur.empty()) out.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    if (!cur.empty()) out.push_back(cur);
    return out;
}

float parse_float(const std::string& tok, const std::string& file, int line, const char* what) {
    errno = 0;
    char* end = nullptr;
    double v = std::strtod(tok.c_str(), &end);
    if (tok.empty() || *end != '\0')
        throw input_error(file, line, std::string(what) + ": '" + tok + "' is not a number");
    if (!std::isfinite(v) || errno == ERANGE || std::fabs(v) > 3.0e38)
        throw input_error(file, line, std::string(what) + ": '" + tok + "' is not finite");
    return static_cast<float>(v);
}

long parse_int(const std::string& tok, const std::string& file, int line, const char* what) {
    errno = 0;
    char* end = nullptr;
    long v = std::strtol(tok.c_str(), &end, 10);
    if (tok.empty() || *end != '\0' || errno == ERANGE)
        throw input_error(file, line, std::string(what) + ": '" + tok + "' is not an integer");
    return v;
}

void for_each_directive(const std::string& path, const char* kind,
                        const std::function<void(int, const std::vector<std::string>&)>& fn) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open " + kind + " file");
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        std::vector<std::string> t = split_tokens(text);
        if (!t.empty()) fn(line, t);
    }
    if (in.bad()) throw InputError(path + ": read error");
}

std::string dir_of(const std::string& path) {
    std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

} // namespace smallmlt
