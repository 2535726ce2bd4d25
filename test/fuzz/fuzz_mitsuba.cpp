// libFuzzer target for the Mitsuba scene reader (XML, transforms, shapes,
// BSDFs, the PLY reader) and the host-side scene preparation. An input is
// the text of s.xml, inc.xml (for <include>), m.obj and m.ply separated by
// NUL bytes, written to a
// private directory and loaded as a render would. InputError is the
// expected answer to bad input; anything else is a finding. Built and run
// by `make fuzz`.
#include "base/error.hpp"
#include "fuzz_files.hpp"
#include "scene/device_scene.hpp"
#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = fuzz::write_parts(data, size, {"s.xml", "inc.xml", "m.obj", "m.ply"});
    try {
        smallmlt::Scene scene = smallmlt::load_scene(path);
        smallmlt::prepare_scene(scene);
    } catch (const smallmlt::InputError&) {
    }
    return 0;
}
