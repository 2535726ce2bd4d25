#include "render/emission_seen.hpp"

#include "scene/sample_layout.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

namespace smallmlt {

EmissionSeenParts emission_seen(const ClContext& cl, cl_program program, const SceneBuffers& scene,
                                const ClBuffer& scratch, std::uint64_t seed,
                                const std::function<bool(std::uint32_t)>& in_cell) {
    EmissionSeenParts parts;
    const std::uint32_t num_lights = scene.frame.num_lights,
                        count = std::uint32_t(scratch.bytes() / (4 * sizeof(float)));
    if (num_lights == 0 || count == 0) return parts;
    ClKernel k(program, "mlt_emission_seen");
    const cl_uint bits = num_lights > 1 ? cl_uint(light_pick_bits(num_lights)) : 0;
    k.set_args(scene, cl_ulong(seed), bits, cl_uint(count), scratch);
    k.run(cl, count);
    std::vector<float> out(4 * std::size_t(count));
    scratch.read(cl, out.data());
    for (std::uint32_t i = 0; i < count; ++i) {
        const float* s = &out[4 * std::size_t(i)];
        if (!(s[0] > 0)) continue;
        std::uint32_t pixel;
        std::memcpy(&pixel, &s[2], sizeof pixel);
        EmissionSeen& e = in_cell(pixel) ? parts.cells : parts.film;
        e.moment += s[0];
        e.luminance = std::max(e.luminance, double(s[1]));
    }
    for (EmissionSeen* e : {&parts.film, &parts.cells})
        e->moment /= double(count);
    return parts;
}

double variance_with_emission_seen(const PixelVariance& v, const EmissionSeen& seen) {
    return std::max(v.value(), std::min(seen.moment, v.one_sample(seen.luminance)));
}

} // namespace smallmlt
