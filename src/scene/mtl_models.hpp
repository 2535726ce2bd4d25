// The model of one MTL material: what a `newmtl` block says, as the reader
// (src/scene/mtl_loader.cpp) collects it, and the Material it becomes. The
// rules are doc/scene-format.md's MTL tables.
#pragma once
#include "base/vec3.hpp"
#include "scene/texture.hpp"
#include "shared_types.h"

#include <optional>
#include <string>
#include <vector>

namespace smallmlt {

// Blender writes the specular exponent as Ns = 1000 (1 - r)^2 for a
// roughness r; the range of Ns that the reader accepts.
constexpr float kMaxNs = 1000.0f;
// Pm at or above this is a metal (below it, not).
constexpr float kMetalPm = 0.5f;

// One directive line of a material, as read.
struct MtlLine {
    std::string directive;
    int line = 0;
    bool nonzero = false; // its value has a non-zero number in it
};

// A texture map a material names: its file (relative to the working
// directory) and the line.
struct MtlMap {
    std::string file;
    int line = 0;
};

// What one `newmtl` block says; what it leaves out keeps these defaults.
struct MtlMaterial {
    std::string name;
    int line = 0; // of its `newmtl`
    Vec3 kd, ks, ke;
    bool has_ks = false;
    std::optional<float> ni, ns, pr;
    float pm = 0; // 0 or >= kMetalPm (the reader rounds the rest to 0)
    float pc = 0, aniso = 0;
    long illum = 1;
    int illum_line = 0;         // the `newmtl` line where no illum is given
    std::vector<MtlLine> lines; // every directive after `newmtl`, in order
    std::optional<MtlMap> map_kd, map_ks, map_pr, map_d;
};

// Roughness in [0, 1] from Ns in [0, kMaxNs], the inverse of Blender's
// export: r = 1 - sqrt(Ns / 1000).
float roughness_from_ns(float ns);

// Roughness of the material: Pr, else from Ns, else 0 (smooth). The
// microfacet alpha is its square.
float mtl_roughness(const MtlMaterial& m);

// A texture the Material needs: which of its fields takes the texture's
// index once loaded, and how its texels are read.
struct MtlTexture {
    u32 Material::*slot;
    MtlMap map;
    TextureKind kind;
    Vec3 MtlMaterial::*constant; // the colour it replaces, or null
};

struct MtlMapping {
    Material material; // its *_tex fields still TEX_NONE
    std::vector<MtlTexture> textures;
    std::vector<MtlLine> ignored; // its lines that change nothing in that model
};

// The Material of `m`. Throws InputError "file:line: material 'NAME': ..."
// (the line of its illum) for an illum out of 0..10, a dielectric without
// Ni or a mirror without Ks.
MtlMapping map_mtl_material(const MtlMaterial& m, const std::string& file);

} // namespace smallmlt
