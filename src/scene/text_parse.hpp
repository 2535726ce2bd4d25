// Line-oriented parsing helpers shared by the scene, OBJ and MTL readers:
// split a line into tokens (a '#' starts a comment) and read strict numbers.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace smallmlt {

// Whitespace-separated tokens of `line` up to a '#'.
std::vector<std::string> split_tokens(const std::string& line);

// Strict conversions: the whole token must be a finite number (an integer
// for parse_int). On failure they throw InputError "file:line: <what>: ...".
float parse_float(const std::string& tok, const std::string& file, int line, const char* what);
long parse_int(const std::string& tok, const std::string& file, int line, const char* what);

// Calls fn(line number, tokens) for every line of `path` that has tokens.
// Throws InputError "path: cannot open <kind> file" or on a read error.
void for_each_directive(const std::string& path, const char* kind,
                        const std::function<void(int, const std::vector<std::string>&)>& fn);

// Directory part of a path with a trailing '/', or "" for a bare name.
std::string dir_of(const std::string& path);

} // namespace smallmlt
