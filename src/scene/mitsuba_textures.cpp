#include "scene/mitsuba_textures.hpp"

#include "base/error.hpp"
#include "scene/text_parse.hpp"
#include "scene/texture.hpp"

#include <algorithm>
#include <cmath>

namespace smallmlt {

namespace {

[[noreturn]] void fail(const XmlObject& o, const std::string& msg) {
    throw input_error(o.where.file, o.where.line, "texture '" + o.type + "': " + msg);
}

// to_uv must be the identity: smallmlt looks textures up at the mesh's uv.
void require_plain_uv(const XmlObject& o) {
    const XmlProperty* p = o.find("to_uv");
    if (p && !xml_transform(o, "to_uv").is_identity())
        throw input_error(p->where.file, p->where.line,
                          "'to_uv' other than the identity is not read (the mesh's uv is used)");
}

SceneTexture bitmap(const XmlObject& o, std::vector<std::string>& warnings) {
    std::string file = xml_string(o, "filename", "");
    if (file.empty()) fail(o, "needs a 'filename'");
    std::string path = file[0] == '/' ? file : dir_of(o.where.file) + file;
    const bool raw = xml_bool(o, "raw", false);
    std::string filter = xml_string(o, "filter_type", "bilinear");
    if (filter != "bilinear" && filter != "nearest")
        fail(o, "filter_type '" + filter + "' is not read (bilinear, nearest)");
    std::string wrap = xml_string(o, "wrap_mode", "repeat");
    if (wrap != "repeat")
        warnings.push_back(o.find("wrap_mode")->where.str() + ": warning: wrap_mode '" + wrap +
                           "' of texture 'bitmap' is read as repeat");
    require_plain_uv(o);
    SceneTexture t =
        load_texture(path, raw ? TextureKind::Data : TextureKind::Colour, o.where.str());
    t.nearest = filter == "nearest";
    return t;
}

// Mitsuba's checkerboard: color0 where the fractional parts of u and v are
// both above 1/2 or both not, else color1, with Mitsuba's v, which is 1 - v
// here (v = 1 the top row). Stored as 8-bit linear values (exact for
// multiples of 1/255, within 1/510 otherwise): the top row is (u < 1/2:
// color0, else color1), the bottom row the reverse.
SceneTexture checkerboard(const XmlObject& o) {
    for (const XmlObject* c : o.children)
        if (c->tag == "texture") fail(o, "a texture inside a checkerboard is not read");
    Vec3 c0 = xml_color(o, "color0", {0.4f, 0.4f, 0.4f}),
         c1 = xml_color(o, "color1", {0.2f, 0.2f, 0.2f});
    require_plain_uv(o);
    auto texel = [&](Vec3 c) {
        const float v[3] = {c.x, c.y, c.z};
        std::uint32_t t = 0xFFu << 24;
        for (int k = 0; k < 3; ++k) {
            if (!(v[k] >= 0 && v[k] <= 1)) fail(o, "colours must lie in [0, 1]");
            t |= std::uint32_t(std::lround(v[k] * 255.0)) << (8 * k);
        }
        return t;
    };
    SceneTexture t;
    t.file = "checkerboard (" + o.where.str() + ")";
    t.kind = TextureKind::Data;
    t.width = t.height = 2;
    t.nearest = true;
    t.texels = {texel(c0), texel(c1), texel(c1), texel(c0)};
    return t;
}

} // namespace

u32 add_mitsuba_texture(const XmlObject& t, Scene& scene, Vec3* mean) {
    SceneTexture tex;
    if (t.type == "bitmap")
        tex = bitmap(t, scene.warnings);
    else if (t.type == "checkerboard")
        tex = checkerboard(t);
    else
        fail(t, "is not read (bitmap and checkerboard are)");
    xml_warn_unread(t, scene.warnings);
    *mean = texture_mean(tex);
    scene.textures.push_back(std::move(tex));
    return static_cast<u32>(scene.textures.size() - 1);
}

} // namespace smallmlt
