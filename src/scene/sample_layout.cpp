#include "scene/sample_layout.hpp"

#include "shared_types.h"

#include <sstream>

namespace smallmlt {

const char* slot_name(Slot s) {
    static const char* names[kSlotCount] = {"BSDF_U",     "BSDF_V",      "LIGHT_U", "LIGHT_V",
                                            "LIGHT_PICK", "BSDF_CHOICE", "RR"};
    return names[s];
}

int light_pick_bits(std::uint32_t num_lights) {
    int bits = 8;
    while (bits < kMaxLightPickBits && (std::uint64_t(1) << (bits - 8)) < num_lights)
        ++bits;
    return bits < kLowBits ? kLowBits : bits;
}

std::uint32_t SceneFeatures::uses() const {
    static const std::uint32_t kUses[MAT_TYPES] = {
#define SMALLMLT_MODEL_USES(NAME, id, uses) uses,
        MAT_MODELS(SMALLMLT_MODEL_USES)
#undef SMALLMLT_MODEL_USES
    };
    std::uint32_t u = 0;
    for (std::uint32_t t = 0; t < MAT_TYPES; ++t)
        if (has(t)) u |= kUses[t];
    return u;
}

SampleLayout make_layout(const SceneFeatures& f, const Roulette& rr) {
    bool want[kSlotCount] = {};
    const std::uint32_t uses = f.uses();
    bool nee = (uses & MAT_USES_NEE) && f.num_lights > 0;
    want[kBsdfU] = want[kBsdfV] = (uses & MAT_USES_PAIR) != 0;
    want[kLightU] = want[kLightV] = nee;
    want[kLightPick] = nee && f.num_lights > 1;
    want[kBsdfChoice] = (uses & MAT_USES_CHOICE) != 0;
    want[kRoulette] = f.depth > rr.start;
    int width[kSlotCount] = {
        kHighBits, kHighBits, kHighBits, kHighBits, light_pick_bits(f.num_lights),
        kLowBits,  kLowBits};
    SampleLayout l;
    l.depth = f.depth;
    l.features = f;
    l.roulette = rr;
    for (int s = 0; s < kSlotCount; ++s) {
        l.index[s] = want[s] ? l.bounce_dims++ : -1;
        l.bits[s] = want[s] ? width[s] : 0;
        l.bounce_bits += l.bits[s];
    }
    return l;
}

std::uint32_t SampleLayout::chain_words(bool float32_states) const {
    if (float32_states) return static_cast<std::uint32_t>(vector_dims());
    return static_cast<std::uint32_t>((vector_bits() + 31) / 32);
}

std::uint32_t SampleLayout::chain_bytes(bool float32_states) const {
    return chain_words(float32_states) * 4u + static_cast<std::uint32_t>(sizeof(ChainValue));
}

std::string SampleLayout::defines() const {
    std::ostringstream d;
    d << "#define LAYOUT_CAMERA_DIMS " << kCameraDims << "u\n";
    d << "#define LAYOUT_BOUNCE_DIMS " << bounce_dims << "u\n";
#define SMALLMLT_MODEL_DEFINE(NAME, id, uses)                                                      \
    d << "#define LAYOUT_HAS_" #NAME " " << (features.has(id) ? 1 : 0) << "\n";
    MAT_MODELS(SMALLMLT_MODEL_DEFINE)
#undef SMALLMLT_MODEL_DEFINE
    d << "#define LAYOUT_HAS_SHADING_NORMALS " << (features.shading_normals ? 1 : 0) << "\n";
    d << "#define LAYOUT_HAS_TEXTURES " << (features.textures ? 1 : 0) << "\n";
    d << "#define LAYOUT_HAS_CUTOUTS " << (features.cutouts ? 1 : 0) << "\n";
    d << "#define LAYOUT_CHOICE_BITS " << kLowBits << "u\n";
    d << "#define LAYOUT_HAS_NEE " << (has(kLightU) ? 1 : 0) << "\n";
    d << "#define LAYOUT_CAMERA_BITS " << kHighBits << "u\n";
    d << "#define LAYOUT_BOUNCE_BITS " << bounce_bits << "u\n";
    d << "#define RR_START_BOUNCE " << roulette.start << "u\n";
    d << std::hexfloat << "#define RR_THRESHOLD " << roulette.threshold << "f\n";
    d << "#define RR_CAP " << roulette.cap << "f\n" << std::defaultfloat;
    d << "#define RR_BY_LUMINANCE " << (roulette.by_luminance ? 1 : 0) << "\n";
    for (int s = 0; s < kSlotCount; ++s) {
        const char* name = slot_name(static_cast<Slot>(s));
        d << "#define SLOT_" << name << " " << index[s] << "\n";
        d << "#define SLOT_" << name << "_BITS " << bits[s] << "u\n";
    }
    // Per-slot bits and bit offsets within a bounce, in slot-index order.
    std::ostringstream slot_bits, slot_offset;
    int offset = 0;
    for (int i = 0; i < bounce_dims; ++i)
        for (int s = 0; s < kSlotCount; ++s)
            if (index[s] == i) {
                slot_bits << (i ? ", " : "") << bits[s] << "u";
                slot_offset << (i ? ", " : "") << offset << "u";
                offset += bits[s];
            }
    if (bounce_dims > 0) {
        d << "__constant uint layout_slot_bits[" << bounce_dims << "] = {" << slot_bits.str()
          << "};\n";
        d << "__constant uint layout_slot_offset[" << bounce_dims << "] = {" << slot_offset.str()
          << "};\n";
    }
    return d.str();
}

} // namespace smallmlt
