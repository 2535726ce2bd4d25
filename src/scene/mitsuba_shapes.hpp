// Shapes of Mitsuba scene files as triangles (doc/scene-format.md, "Mitsuba
// scenes"): obj and ply meshes, and rectangle, cube, disk and sphere tessellated
// finely enough that the tessellation is below noise: every curved edge in
// kCurveSegments straight pieces, whose sagitta is below 1e-3 of the radius,
// with the vertices moved out so that the mesh has the surface's exact area
// (an emitter's power is exact); a sphere's shading normals are its own.
#pragma once
#include "scene/mitsuba_xml.hpp"
#include "scene/scene.hpp"

namespace smallmlt {

constexpr int kCurveSegments = 72; // 1 - cos(pi / 72) = 9.5e-4
constexpr int kSphereRings = kCurveSegments / 2;

// Appends the triangles of shape `o` (obj, ply, rectangle, cube, disk, sphere),
// all of material `material`, to scene.triangles. Throws InputError at the
// shape's line for an unknown type or a bad parameter.
void add_mitsuba_shape(const XmlObject& o, std::uint32_t material, Scene& scene);

} // namespace smallmlt
