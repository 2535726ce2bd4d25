// What the fuzz targets share: an input split at its first NUL bytes into
// the files of a scene, written to a private directory.
#pragma once
#include <cstdint>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace fuzz {

// The process's own directory under /tmp.
inline const std::string& work_dir() {
    static const std::string dir = [] {
        std::string d = "/tmp/smallmlt-fuzz-" + std::to_string(getpid());
        mkdir(d.c_str(), 0700);
        return d;
    }();
    return dir;
}

// Writes the input's parts, split at its first names.size() - 1 NUL bytes,
// to the files `names` in work_dir(); returns the path of the first.
inline std::string write_parts(const std::uint8_t* data, std::size_t size,
                               const std::vector<std::string>& names) {
    std::vector<std::string> part(names.size());
    for (std::size_t i = 0, k = 0; i < size; ++i) {
        if (data[i] == '\0' && k + 1 < names.size())
            ++k;
        else
            part[k] += char(data[i]);
    }
    for (std::size_t k = 0; k < names.size(); ++k)
        std::ofstream(work_dir() + "/" + names[k], std::ios::binary | std::ios::trunc) << part[k];
    return work_dir() + "/" + names[0];
}

} // namespace fuzz
