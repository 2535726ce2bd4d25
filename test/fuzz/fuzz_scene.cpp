// libFuzzer target for the scene, OBJ and MTL loaders and the host-side
// scene preparation (BVH, light table, sample layout). An input is the text
// of s.scene, m.obj and m.mtl separated by NUL bytes; they are written to a
// private directory and loaded as a render would. InputError is the expected
// answer to bad input; anything else (a crash, a sanitizer report, another
// exception) is a finding. Built and run by `make fuzz`.
#include "scene/device_scene.hpp"
#include "base/error.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace {

const std::string& work_dir() {
    static const std::string dir = [] {
        std::string d = "/tmp/smallmlt-fuzz-" + std::to_string(getpid());
        mkdir(d.c_str(), 0700);
        return d;
    }();
    return dir;
}

void write_file(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string in(reinterpret_cast<const char*>(data), size);
    std::string part[3];
    for (std::size_t i = 0, k = 0; i < in.size(); ++i) {
        if (in[i] == '\0' && k < 2)
            ++k;
        else
            part[k] += in[i];
    }
    const std::string& dir = work_dir();
    write_file(dir + "/s.scene", part[0]);
    write_file(dir + "/m.obj", part[1]);
    write_file(dir + "/m.mtl", part[2]);
    try {
        smallmlt::Scene scene = smallmlt::load_scene(dir + "/s.scene");
        smallmlt::prepare_scene(scene);
    } catch (const smallmlt::InputError&) {
    }
    return 0;
}
