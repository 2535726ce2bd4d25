// Error kinds and their exit codes: a usage error (bad flag or value on the
// command line) exits 2, an input error (bad scene, OBJ, MTL, image or device
// trouble) exits 1. Messages name the file and line or the flag.
#pragma once
#include <stdexcept>
#include <string>

namespace smallmlt {

constexpr int kExitInputError = 1;
constexpr int kExitUsageError = 2;

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "file:line: message"
inline InputError input_error(const std::string& file, int line, const std::string& msg) {
    return InputError(file + ":" + std::to_string(line) + ": " + msg);
}

} // namespace smallmlt
