// Textures of Mitsuba scene files as scene textures (doc/scene-format.md,
// "Mitsuba scenes"): bitmap (an image file, bilinear or nearest, repeated)
// and checkerboard (two constant colours, exact: a 2x2 texture looked up at
// the nearest texel).
#pragma once
#include "scene/mitsuba_xml.hpp"
#include "scene/scene.hpp"

namespace smallmlt {

// Appends texture object `t` to scene.textures as colour values; returns its
// index and sets *mean to its mean linear colour (a material's constant
// where one is needed). Throws InputError at the texture's (or the
// parameter's) line for another type or a parameter it cannot render.
u32 add_mitsuba_texture(const XmlObject& t, Scene& scene, Vec3* mean);

} // namespace smallmlt
