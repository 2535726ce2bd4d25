// libFuzzer target for the scene, OBJ and MTL loaders and the host-side
// scene preparation (BVH, light table, sample layout). An input is the text
// of s.scene, m.obj and m.mtl separated by NUL bytes; they are written to a
// private directory and loaded as a render would. InputError is the expected
// answer to bad input; anything else (a crash, a sanitizer report, another
// exception) is a finding. Built and run by `make fuzz`.
#include "base/error.hpp"
#include "fuzz_files.hpp"
#include "scene/device_scene.hpp"
#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = fuzz::write_parts(data, size, {"s.scene", "m.obj", "m.mtl"});
    try {
        smallmlt::Scene scene = smallmlt::load_scene(path);
        smallmlt::prepare_scene(scene);
    } catch (const smallmlt::InputError&) {
    }
    return 0;
}
