// Reader of Mitsuba scene files, versions 0.5/0.6 and 3 (doc/scene-format.md,
// "Mitsuba scenes"): the XML as objects (shape, bsdf, emitter, ...) with
// their properties and children. It merges <include>s, substitutes $name
// from <default>s, resolves <ref>s and, for files older than version 2,
// renames camelCase names as Mitsuba 3 does (toWorld -> to_world). Every
// object and property keeps its file and line for messages.
#pragma once
#include "base/vec3.hpp"
#include "scene/mitsuba_transform.hpp"

#include <deque>
#include <map>
#include <string>
#include <vector>

namespace smallmlt {

struct XmlWhere {
    std::string file;
    int line = 0;
    std::string str() const { return file + ":" + std::to_string(line); }
};

// A property: its tag (float, integer, boolean, string, rgb, spectrum,
// point, vector or transform), name and value.
struct XmlProperty {
    std::string tag, name;
    std::vector<double> numbers; // float, integer: 1; rgb, point, vector: 3; spectrum: 1 (uniform)
    std::string text;            // string; boolean: "true" or "false"
    Mat4 transform;
    // A transform of one <lookat>: its origin, target and up as written.
    bool is_lookat = false;
    Vec3 lookat[3];
    XmlWhere where;
    mutable bool read = false; // set by the accessors; unread ones are warned about
};

struct XmlObject {
    std::string tag, type, id, name; // tag: shape, bsdf, emitter, sensor, film, ...
    XmlWhere where;
    std::vector<XmlProperty> properties;
    std::vector<const XmlObject*> children; // nested or by <ref>, in file order

    const XmlProperty* find(const std::string& prop_name) const;
    // "bsdf 'diffuse' (FILE:LINE)", for messages.
    std::string what() const;
};

struct XmlDocument {
    std::deque<XmlObject> objects; // storage; objects[0] is the <scene>
    std::vector<std::string> warnings;
    const XmlObject& root() const { return objects.front(); }
};

// Reads `path` and what it includes. Throws InputError naming the file and
// line of the first problem.
XmlDocument read_mitsuba_xml(const std::string& path);

// Typed reads of an object's properties; each marks the property read and
// throws InputError at the property's line if it has another type.
double xml_float(const XmlObject& o, const std::string& name, double fallback);
long xml_int(const XmlObject& o, const std::string& name, long fallback);
bool xml_bool(const XmlObject& o, const std::string& name, bool fallback);
std::string xml_string(const XmlObject& o, const std::string& name, const std::string& fallback);
// rgb, a uniform spectrum or a float (all three channels).
Vec3 xml_color(const XmlObject& o, const std::string& name, Vec3 fallback);
Vec3 xml_point(const XmlObject& o, const std::string& name, Vec3 fallback);
Mat4 xml_transform(const XmlObject& o, const std::string& name);

// Warns, into `warnings`, about every property of `o` that no accessor read:
// "FILE:LINE: warning: 'NAME' of bsdf 'diffuse' is not read (ignored)".
void xml_warn_unread(const XmlObject& o, std::vector<std::string>& warnings);

// The camelCase to snake_case rename of Mitsuba 3's upgrade of old files:
// before each upper-case letter that follows a lower-case one, '_', and that
// letter and the upper-case ones right after it in lower case.
std::string xml_snake_case(const std::string& name);

} // namespace smallmlt
