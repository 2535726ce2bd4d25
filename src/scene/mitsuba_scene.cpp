// A Mitsuba scene file as a Scene (doc/scene-format.md, "Mitsuba scenes"):
// the sensor and its film, the integrator's depth, and the shapes with
// their BSDFs and area emitters.
#include "base/error.hpp"
#include "scene/material.hpp"
#include "scene/mitsuba_bsdfs.hpp"
#include "scene/mitsuba_shapes.hpp"
#include "scene/mitsuba_xml.hpp"
#include "scene/scene.hpp"

#include <array>
#include <cmath>
#include <map>

namespace smallmlt {

namespace {

[[noreturn]] void fail(const XmlObject& o, const std::string& msg) {
    throw input_error(o.where.file, o.where.line, msg);
}

std::string warning(const XmlObject& o, const std::string& msg) {
    return o.where.str() + ": warning: " + msg;
}

std::vector<const XmlObject*> children(const XmlObject& o, const char* tag) {
    std::vector<const XmlObject*> out;
    for (const XmlObject* c : o.children)
        if (c->tag == tag) out.push_back(c);
    return out;
}

// Mitsuba's fov along `axis` of a width x height film as the vertical fov.
double vertical_fov_deg(const XmlObject& s, double fov_deg, const std::string& axis, int width,
                        int height) {
    const double aspect = double(width) / height;
    const double t = std::tan(fov_deg * M_PI / 360);
    double ty; // tan(fov_y / 2)
    std::string a = axis;
    if (a == "smaller") a = aspect > 1 ? "y" : "x";
    if (a == "larger") a = aspect > 1 ? "x" : "y";
    if (a == "x")
        ty = t / aspect;
    else if (a == "y")
        ty = t;
    else if (a == "diagonal")
        ty = t / std::sqrt(1 + aspect * aspect);
    else
        fail(s, "fov_axis '" + axis + "' is not x, y, diagonal, smaller or larger");
    return 2 * std::atan(ty) * 180 / M_PI;
}

void read_film(const XmlObject& sensor, Scene& scene) {
    std::vector<const XmlObject*> films = children(sensor, "film");
    if (films.size() > 1) fail(*films[1], "a sensor has one film");
    if (films.empty()) {
        scene.width = 768, scene.height = 576;
        return;
    }
    const XmlObject& f = *films[0];
    if (f.type != "hdrfilm")
        scene.warnings.push_back(warning(f, "film '" + f.type + "' is read as hdrfilm"));
    long w = xml_int(f, "width", 768), h = xml_int(f, "height", 576);
    if (w < 1 || h < 1 || w > kMaxFilmSide || h > kMaxFilmSide)
        fail(f, "film size must be 1.." + std::to_string(kMaxFilmSide) + " pixels on each side");
    scene.width = int(w), scene.height = int(h);
    for (const XmlObject* r : children(f, "rfilter"))
        if (r->type != "box")
            scene.warnings.push_back(
                warning(*r, "reconstruction filter '" + r->type + "' is replaced by a box"));
    if (children(f, "rfilter").empty())
        scene.warnings.push_back(
            warning(f, "the film's default filter (gaussian) is replaced by a box"));
    for (const char* ignored : {"file_format", "pixel_format", "component_format"})
        if (const XmlProperty* p = f.find(ignored)) p->read = true; // output format: --out decides
    xml_warn_unread(f, scene.warnings);
}

void read_sensor(const XmlObject& root, Scene& scene) {
    std::vector<const XmlObject*> sensors = children(root, "sensor");
    if (sensors.empty()) fail(root, "the scene has no <sensor>");
    if (sensors.size() > 1) fail(*sensors[1], "a second <sensor> (one is read)");
    const XmlObject& s = *sensors[0];
    if (s.type != "perspective") fail(s, "sensor '" + s.type + "' is not read (perspective is)");
    read_film(s, scene);
    Mat4 m = xml_transform(s, "to_world");
    // No scale, no mirror: the columns of the linear part are orthonormal.
    for (int j = 0; j < 3; ++j) {
        Vec3 c{float(m.m[0][j]), float(m.m[1][j]), float(m.m[2][j])};
        if (std::abs(length(c) - 1) > 1e-4f)
            fail(s, "the sensor's to_world scales (Mitsuba does not allow it)");
    }
    if (!(m.det3() > 0)) fail(s, "the sensor's to_world mirrors the image");
    const XmlProperty* tw = s.find("to_world");
    if (tw && tw->is_lookat) { // as written: the camera of a .scene file's numbers
        scene.camera.eye = tw->lookat[0];
        scene.camera.target = tw->lookat[1];
        scene.camera.up = tw->lookat[2];
    } else {
        scene.camera.eye = m.point({0, 0, 0});
        scene.camera.target = m.point({0, 0, 1});
        scene.camera.up = normalize(m.vector({0, 1, 0}));
    }
    if (s.find("focal_length")) fail(s, "'focal_length' is not read (give 'fov')");
    double fov = xml_float(s, "fov", -1);
    if (fov == -1) fail(s, "the sensor needs a 'fov' (degrees)");
    if (!(fov > 0 && fov < 180)) fail(s, "'fov' must be in (0, 180) degrees");
    std::string axis = xml_string(s, "fov_axis", "x");
    scene.camera.fov_y_deg =
        float(axis == "y" ? fov : vertical_fov_deg(s, fov, axis, scene.width, scene.height));
    for (const char* clip : {"near_clip", "far_clip"})
        if (const XmlProperty* p = s.find(clip)) {
            p->read = true;
            scene.warnings.push_back(p->where.str() + ": warning: '" + clip +
                                     "' is not read (rays start at the eye and are not cut)");
        }
    for (const XmlObject* smp : children(s, "sampler")) {
        if (const XmlProperty* p = smp->find("sample_count")) p->read = true;
        scene.warnings.push_back(warning(*smp, "the sampler is not read (--spp or --time sets "
                                               "the samples; smallmlt's own numbers)"));
    }
    xml_warn_unread(s, scene.warnings);
}

void read_integrator(const XmlObject& root, Scene& scene) {
    std::vector<const XmlObject*> its = children(root, "integrator");
    long max_depth = -1;
    if (its.size() > 1) fail(*its[1], "a second <integrator> (one is read)");
    if (!its.empty()) {
        const XmlObject& it = *its[0];
        if (it.type != "path")
            scene.warnings.push_back(warning(it, "integrator '" + it.type + "' is read as path"));
        max_depth = xml_int(it, "max_depth", -1);
        if (max_depth < -1 || max_depth == 0)
            fail(it, "max_depth must be -1 (no limit) or at least 1");
        if (const XmlProperty* p = it.find("rr_depth")) {
            p->read = true;
            scene.warnings.push_back(p->where.str() +
                                     ": warning: 'rr_depth' is not read (--rr-start sets it)");
        }
        if (xml_bool(it, "hide_emitters", false)) fail(it, "hide_emitters is not read");
        if (it.type == "path") xml_warn_unread(it, scene.warnings);
    }
    // Mitsuba's max_depth counts the segment from the camera: 1 is the
    // lights seen directly, smallmlt's depth 0.
    if (max_depth == -1) {
        scene.depth = kMaxDepth;
        scene.warnings.push_back((its.empty() ? root.where.str() : its[0]->where.str()) +
                                 ": warning: max_depth -1 (no limit) is read as " +
                                 std::to_string(kMaxDepth) + " bounces");
    } else {
        scene.depth = int(std::min<long>(max_depth - 1, kMaxDepth));
        if (max_depth - 1 > kMaxDepth)
            scene.warnings.push_back(its[0]->where.str() + ": warning: max_depth " +
                                     std::to_string(max_depth) + " is read as " +
                                     std::to_string(kMaxDepth) + " bounces");
    }
}

void read_shapes(const XmlObject& root, Scene& scene) {
    // One material per (BSDF object, emitted radiance).
    std::map<std::pair<const XmlObject*, std::array<float, 3>>, std::uint32_t> made;
    for (const XmlObject* c : root.children) {
        if (c->tag == "emitter")
            fail(*c, "emitter '" + c->type +
                         "' is not read: only area emitters on shapes are, for now");
        if (c->tag != "shape") continue;
        const XmlObject& shape = *c;
        std::vector<const XmlObject*> bsdfs = children(shape, "bsdf");
        std::vector<const XmlObject*> emitters = children(shape, "emitter");
        if (bsdfs.size() > 1) fail(*bsdfs[1], "a shape has one bsdf");
        if (emitters.size() > 1) fail(*emitters[1], "a shape has one emitter");
        std::array<float, 3> radiance{0, 0, 0};
        if (!emitters.empty()) {
            const XmlObject& e = *emitters[0];
            if (e.type != "area") fail(e, "emitter '" + e.type + "' on a shape (area is read)");
            Vec3 l = xml_color(e, "radiance", {1, 1, 1});
            if (!(l.x >= 0 && l.y >= 0 && l.z >= 0)) fail(e, "radiance must not be negative");
            radiance = {l.x, l.y, l.z};
            xml_warn_unread(e, scene.warnings);
        }
        const XmlObject* bsdf = bsdfs.empty() ? nullptr : bsdfs[0];
        auto key = std::make_pair(bsdf, radiance);
        auto it = made.find(key);
        std::uint32_t index;
        if (it != made.end()) {
            index = it->second;
        } else {
            Material m =
                bsdf ? mitsuba_material(*bsdf, scene) : mitsuba_default_material(!emitters.empty());
            set_emission(m, {radiance[0], radiance[1], radiance[2]});
            index = std::uint32_t(scene.materials.size());
            scene.materials.push_back(m);
            scene.material_names.push_back(bsdf ? (bsdf->id.empty() ? bsdf->type : bsdf->id)
                                                : "default");
            made.emplace(key, index);
        }
        add_mitsuba_shape(shape, index, scene);
        xml_warn_unread(shape, scene.warnings);
    }
    if (scene.triangles.empty()) fail(root, "the scene has no shape with a triangle");
}

} // namespace

Scene load_mitsuba_scene(const std::string& path) {
    XmlDocument doc = read_mitsuba_xml(path);
    Scene scene;
    scene.warnings = doc.warnings;
    const XmlObject& root = doc.root();
    read_sensor(root, scene);
    read_integrator(root, scene);
    read_shapes(root, scene);
    require_lit(scene, path);
    return scene;
}

} // namespace smallmlt
