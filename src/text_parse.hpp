// Line-oriented parsing helpers shared by the scene, OBJ and MTL readers:
// split a line into tokens (a '#' starts a comment) and read strict numbers.
#pragma once
#include <string>
#include <vector>

namespace smallmlt {

// Whitespace-separated tokens of `line` up to a '#'.
std::vector<std::string> split_tokens(const std::string& line);

// Strict conversions: the whole token must be a finite number (an integer
// for parse_int). On failure they throw InputError "file:line: <what>: ...".
float parse_float(const std::string& tok, const std::string& file, int line, const char* what);
long parse_int(const std::string& tok, const std::string& file, int line, const char* what);

// Directory part of a path with a trailing '/', or "" for a bare name.
std::string dir_of(const std::string& path);

} // namespace smallmlt
