// Textures of a scene: images read with stb_image and kept as 8-bit RGBA
// texels (sRGB-encoded for colour maps), the form the device stores
// (TextureInfo, cl/core/shared_types.h), and halved where memory asks.
#pragma once
#include "base/vec3.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace smallmlt {

// What a texture's texels mean: a colour (sRGB-encoded, decoded at lookup),
// linear data (roughness, read from its first channel) or a cut-out mask
// (its alpha channel, or its first channel where the image has no alpha).
enum class TextureKind { Colour, Data, Mask };

struct SceneTexture {
    std::string file; // as the material named it, for messages and `budget`
    TextureKind kind = TextureKind::Colour;
    int width = 0, height = 0;
    std::vector<std::uint32_t> texels; // RGBA, R in the low byte, top row first
    int halvings = 0;                  // times halved to fit (or by --texture-max)
    bool nearest = false;              // looked up at the nearest texel, not bilinearly

    std::uint64_t bytes() const { return texels.size() * 4ull; }
};

// Reads an image file (PNG, JPEG, BMP, TGA, ...). Throws InputError
// "where: cannot read texture FILE: reason".
SceneTexture load_texture(const std::string& path, TextureKind kind, const std::string& where);

// The mean of the texels' RGB: linear light for colours, the values for
// data and masks.
Vec3 texture_mean(const SceneTexture& t);

// Halves both sides (a 2x2 box filter, in linear light for colours; a side
// of 1 stays 1).
void halve(SceneTexture& t);

// sRGB encoding of 8-bit values, both ways (IEC 61966-2-1).
double srgb_to_linear(double c);
double linear_to_srgb(double c);

// Halves the largest textures until their texels total at most max_bytes
// and none has a side above max_side (0: no cap). Returns how many
// halvings it made.
int fit_textures(std::vector<SceneTexture>& textures, std::uint64_t max_bytes, int max_side);

} // namespace smallmlt
