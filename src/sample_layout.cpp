#include "sample_layout.hpp"

#include <sstream>

namespace smallmlt {

const char* slot_name(Slot s) {
    static const char* names[kSlotCount] = {"BSDF_U",     "BSDF_V",  "LIGHT_U", "LIGHT_V",
                                            "LIGHT_PICK", "FRESNEL", "RR"};
    return names[s];
}

int light_pick_bits(std::uint32_t num_lights) {
    int bits = 8;
    while (bits < kMaxLightPickBits && (std::uint64_t(1) << (bits - 8)) < num_lights)
        ++bits;
    return bits < kLowBits ? kLowBits : bits;
}

SampleLayout make_layout(const SceneFeatures& f) {
    bool want[kSlotCount] = {};
    bool nee = f.diffuse && f.num_lights > 0;
    want[kBsdfU] = want[kBsdfV] = f.diffuse;
    want[kLightU] = want[kLightV] = nee;
    want[kLightPick] = nee && f.num_lights > 1;
    want[kFresnel] = f.dielectric;
    want[kRoulette] = f.depth > kRouletteStart;
    int width[kSlotCount] = {
        kHighBits, kHighBits, kHighBits, kHighBits, light_pick_bits(f.num_lights),
        kLowBits,  kLowBits};
    SampleLayout l;
    l.depth = f.depth;
    l.features = f;
    for (int s = 0; s < kSlotCount; ++s) {
        l.index[s] = want[s] ? l.bounce_dims++ : -1;
        l.bits[s] = want[s] ? width[s] : 0;
        l.bounce_bits += l.bits[s];
    }
    return l;
}

std::string SampleLayout::defines() const {
    std::ostringstream d;
    d << "#define LAYOUT_CAMERA_DIMS " << kCameraDims << "u\n";
    d << "#define LAYOUT_BOUNCE_DIMS " << bounce_dims << "u\n";
    d << "#define LAYOUT_HAS_DIFFUSE " << (features.diffuse ? 1 : 0) << "\n";
    d << "#define LAYOUT_HAS_MIRROR " << (features.mirror ? 1 : 0) << "\n";
    d << "#define LAYOUT_HAS_DIELECTRIC " << (features.dielectric ? 1 : 0) << "\n";
    d << "#define LAYOUT_HAS_NEE " << (has(kLightU) ? 1 : 0) << "\n";
    d << "#define LIGHT_PICK_BITS " << (has(kLightPick) ? bits[kLightPick] : kLowBits) << "u\n";
    d << "#define RR_START_BOUNCE " << kRouletteStart << "u\n";
    for (int s = 0; s < kSlotCount; ++s)
        d << "#define SLOT_" << slot_name(static_cast<Slot>(s)) << " " << index[s] << "\n";
    return d.str();
}

} // namespace smallmlt
