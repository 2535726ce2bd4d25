// The per-scene layout of a path's primary-sample numbers: which slots each
// bounce has and how many bits each is stored in. "Model no more than a scene
// needs": a slot exists only if the scene's materials and lights use it.
#pragma once
#include "shared_types.h"

#include <cstdint>
#include <string>

namespace smallmlt {

// What a scene's paths can do, which decides the layout.
struct SceneFeatures {
    std::uint32_t models = 0;     // bit t: a triangle has a material of type t (MAT_MODELS)
    std::uint32_t num_lights = 0; // emissive triangles
    int depth = 0;
    bool shading_normals = false; // some triangle has interpolated normals
    bool textures = false;        // some material has a texture
    bool cutouts = false;         // some material has a cut-out texture

    bool has(std::uint32_t type) const { return (models >> type & 1u) != 0; }
    SceneFeatures& with(std::uint32_t type) {
        models |= 1u << type;
        return *this;
    }
    // The union of the MAT_USES_* of its models: the numbers a bounce reads.
    std::uint32_t uses() const;
};

// Russian roulette (cl/path/path.cl, path_survives): after scattering at a bounce
// >= start, a path whose throughput measure m (its largest channel, or its
// luminance) gives p = min(cap, m / threshold) < 1 survives with probability
// p and is divided by it. The defaults were chosen by equal-time error over
// the bench scenes (doc/RESULTS.md); classic() is the rule of earlier
// versions, kept for comparison.
struct Roulette {
    int start = 3;
    float threshold = 0.3f;
    float cap = 1.0f;
    bool by_luminance = false;
    static Roulette classic() { return {3, 1.0f, 0.95f, false}; }
};

// Slots by kind: the BSDF pair, the light pair, the light pick, the BSDF's
// lobe choice and Russian roulette.
enum Slot : int {
    kBsdfU,
    kBsdfV,
    kLightU,
    kLightV,
    kLightPick,
    kBsdfChoice,
    kRoulette,
    kSlotCount
};

constexpr int kHighBits = 24;  // continuous slots (BSDF and light sampling)
constexpr int kLowBits = 16;   // discrete choices
constexpr int kCameraDims = 2; // film position, kHighBits each
constexpr int kMaxLightPickBits = 24;

struct SampleLayout {
    int index[kSlotCount]; // position within a bounce, -1 if absent; high-precision first
    int bits[kSlotCount];  // stored bits (0 if absent)
    int bounce_dims = 0;   // numbers per bounce
    int bounce_bits = 0;   // stored bits per bounce
    int depth = 0;
    SceneFeatures features;
    Roulette roulette;

    bool has(Slot s) const { return index[s] >= 0; }
    int vector_dims() const { return kCameraDims + depth * bounce_dims; }
    int vector_bits() const { return kCameraDims * kHighBits + depth * bounce_bits; }
    // A chain's state (cl/sampling/pss.cl): 32-bit words of its numbers, packed at
    // their slots' precision or one float32 per number (the reference
    // build), and the bytes it keeps in all, words and ChainValue.
    std::uint32_t chain_words(bool float32_states) const;
    std::uint32_t chain_bytes(bool float32_states) const;
    // OpenCL preprocessor definitions (LAYOUT_*, SLOT_*) for the kernels:
    // the layout and which material models the kernels compile in.
    std::string defines() const;
};

const char* slot_name(Slot s);

// Width of the light-pick slot for n lights: 16 bits, widened so that each
// light gets at least 2^8 grid points on average, at most 24 bits.
int light_pick_bits(std::uint32_t num_lights);

SampleLayout make_layout(const SceneFeatures& f, const Roulette& rr = Roulette());

} // namespace smallmlt
