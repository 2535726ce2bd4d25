// BSDFs of Mitsuba scene files as smallmlt's materials (doc/scene-format.md,
// "Mitsuba scenes"): diffuse, twosided, conductor, roughconductor,
// dielectric, roughdielectric, thindielectric, plastic and roughplastic,
// with Mitsuba 3's parameter names and defaults, reflectances given as
// textures (src/scene/mitsuba_textures.cpp); one-sided unless wrapped in
// twosided.
#pragma once
#include "scene/mitsuba_xml.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace smallmlt {

// The material of `bsdf`; its textures are appended to scene.textures, and
// what it reads but cannot render goes to scene.warnings. Throws InputError
// at the BSDF's (or the parameter's) line.
Material mitsuba_material(const XmlObject& bsdf, Scene& scene);

// A shape's material without a BSDF: Mitsuba's diffuse of reflectance 0.5,
// or 0 on an emitter.
Material mitsuba_default_material(bool emitter);

// The index of refraction of a name of Mitsuba's table ("bk7", "water",
// ...; case-insensitive), or a negative value for an unknown name.
double mitsuba_named_ior(const std::string& name);

// A conductor of Mitsuba's table ("Cu", "Au", ...; case-sensitive, "none"
// for eta 0, k 1): false for an unknown name.
bool mitsuba_named_conductor(const std::string& name, Vec3& eta, Vec3& k);

} // namespace smallmlt
