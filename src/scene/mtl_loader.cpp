// Reader of MTL material files as modelling tools write them: every
// directive of doc/scene-format.md's MTL table is read and checked (an error
// names file and line), the model is chosen in src/scene/mtl_models.cpp, and
// what the models cannot show gives one warning per file and directive.
#include "base/error.hpp"
#include "scene/mtl_models.hpp"
#include "scene/scene.hpp"
#include "scene/text_parse.hpp"

#include <algorithm>
#include <map>

namespace smallmlt {

namespace {

// The warnings of one MTL file: one per kind, at the first line that gave
// it, with the number of lines that did.
class FileWarnings {
  public:
    // `ignored`: the line's directive is left out (said in the count).
    void add(const std::string& key, int line, const std::string& text, bool ignored) {
        auto [it, fresh] = index_.emplace(key, entries_.size());
        if (fresh) {
            entries_.push_back({line, 1, text, ignored});
            return;
        }
        Entry& e = entries_[it->second];
        ++e.count;
        if (line < e.line) { // lines of one kind come in order; kept safe
            e.line = line;
            e.text = text;
        }
    }

    void append_to(std::vector<std::string>& out, const std::string& file) const {
        std::vector<Entry> sorted = entries_;
        std::stable_sort(sorted.begin(), sorted.end(),
                         [](const Entry& a, const Entry& b) { return a.line < b.line; });
        for (const Entry& e : sorted)
            out.push_back(file + ":" + std::to_string(e.line) + ": warning: " + e.text + " (" +
                          (e.ignored ? "ignored; " : "") + std::to_string(e.count) +
                          (e.count == 1 ? " line)" : " lines)"));
    }

  private:
    struct Entry {
        int line, count;
        std::string text;
        bool ignored;
    };
    std::vector<Entry> entries_;
    std::map<std::string, std::size_t> index_;
};

// Texture maps the models read.
const char* const kReadMaps[] = {"map_Kd", "map_Ks", "map_Pr", "map_d"};

// Texture maps of a value the models have but do not take a texture for,
// the constant used instead and why.
const std::map<std::string, std::pair<std::string, std::string>> kUnreadMaps = {
    {"map_Ke", {"Ke", "emission is not textured"}},
    {"map_Ns", {"Ns", "the roughness map is map_Pr"}},
    {"map_Pm", {"Pm", "a material is metal or not"}}};

// Maps of what no model has (warned about in mtl_models.cpp).
bool is_other_map(const std::string& d) {
    for (const char* n : {"map_Ka", "map_Bump", "map_bump", "bump", "norm", "disp", "decal", "refl",
                          "map_refl", "map_Ps", "map_Pc", "map_Pcr"})
        if (d == n) return true;
    return false;
}

// Numbers read and checked, whose value no model uses.
bool is_ignored_number(const std::string& d) {
    for (const char* n : {"Pcr", "anisor", "sharpness"})
        if (d == n) return true;
    return false;
}

class MtlReader {
  public:
    MtlReader(const std::string& path, Scene& scene) : path_(path), scene_(scene) {}

    void directive(int line, const std::vector<std::string>& t) {
        const std::string& d = t[0];
        if (d == "newmtl") {
            if (t.size() != 2) throw input_error(path_, line, "'newmtl' takes one name");
            finish();
            cur_ = MtlMaterial();
            cur_.name = t[1];
            cur_.line = cur_.illum_line = line;
            open_ = true;
            return;
        }
        if (!open_) throw input_error(path_, line, "'" + d + "' before any 'newmtl'");
        MtlLine l{d, line, false};
        if (d == "Kd" || d == "Ks" || d == "Ke") {
            Vec3 c = rgb(t, line, d == "Ke" ? 3.0e38f : 1.0f);
            l.nonzero = c.x != 0 || c.y != 0 || c.z != 0;
            (d == "Kd" ? cur_.kd : d == "Ks" ? cur_.ks : cur_.ke) = c;
            cur_.has_ks = cur_.has_ks || d == "Ks";
        } else if (d == "Ka" || d == "Tf") {
            if (t.size() < 2) throw input_error(path_, line, "'" + d + "' takes a colour");
            for (std::size_t i = 1; i < t.size(); ++i)
                parse_float(t[i], path_, line, d.c_str());
        } else if (d == "Ni") {
            float v = number(t, line);
            if (!(v > 0)) throw input_error(path_, line, "'Ni' must be > 0");
            cur_.ni = v;
        } else if (d == "Ns") {
            cur_.ns = number_in(t, line, 0.0f, kMaxNs);
        } else if (d == "Pr") {
            cur_.pr = number_in(t, line, 0.0f, 1.0f);
        } else if (d == "Pm") {
            cur_.pm = metallic(t, line);
            l.nonzero = cur_.pm != 0;
        } else if (d == "Pc" || d == "Ps" || d == "aniso") {
            float v = number(t, line);
            l.nonzero = v != 0;
            if (d == "Pc") cur_.pc = v;
            if (d == "aniso") cur_.aniso = v;
        } else if (is_ignored_number(d)) {
            number(t, line);
        } else if (d == "d" || d == "Tr") {
            opacity(t, line);
        } else if (d == "illum") {
            if (t.size() != 2) throw input_error(path_, line, "'illum' takes one integer");
            cur_.illum = parse_int(t[1], path_, line, "illum"); // checked at the end
            cur_.illum_line = line;
            if (cur_.illum == 10)
                warnings_.add("illum 10", line,
                              "illum 10: the shadow matte is not modelled; the material "
                              "renders as with illum 1",
                              false);
        } else if (std::find(std::begin(kReadMaps), std::end(kReadMaps), d) !=
                   std::end(kReadMaps)) {
            MtlMap map{dir_of(path_) + map_file(t, line), line};
            (d == "map_Kd"   ? cur_.map_kd
             : d == "map_Ks" ? cur_.map_ks
             : d == "map_Pr" ? cur_.map_pr
                             : cur_.map_d) = map;
        } else if (kUnreadMaps.count(d)) {
            map_file(t, line);
            const auto& [constant, why] = kUnreadMaps.at(d);
            warnings_.add(d, line,
                          "'" + d + "' is not read (" + why + "): the constant '" + constant +
                              "' is used, or its default",
                          true);
        } else if (is_other_map(d)) {
            map_file(t, line);
        } else {
            throw input_error(path_, line, "unsupported material directive '" + d + "'");
        }
        cur_.lines.push_back(l);
    }

    // Adds the last material and the file's warnings to the scene.
    void end() {
        finish();
        warnings_.append_to(scene_.warnings, path_);
    }

  private:
    void finish() {
        if (!open_) return;
        open_ = false;
        for (const std::string& n : scene_.material_names)
            if (n == cur_.name)
                throw input_error(path_, cur_.line,
                                  "material '" + cur_.name + "' is defined twice");
        MtlMapping m = map_mtl_material(cur_, path_);
        for (const MtlLine& l : m.ignored)
            warnings_.add(l.directive, l.line,
                          "'" + l.directive + "' changes nothing in these models", true);
        // A colour map's constant becomes the image's mean, as for Mitsuba's
        // textures: the model's choice weights (plastic's) follow the image,
        // not the Kd an exporter writes beside it.
        MtlMaterial means = cur_;
        bool remap = false;
        for (const MtlTexture& t : m.textures)
            if (t.constant) {
                means.*t.constant = texture_mean(scene_.textures[texture_index(t)]);
                remap = true;
            }
        if (remap) m.material = map_mtl_material(means, path_).material;
        for (const MtlTexture& t : m.textures)
            m.material.*t.slot = texture_index(t);
        scene_.materials.push_back(m.material);
        scene_.material_names.push_back(cur_.name);
    }

    Vec3 rgb(const std::vector<std::string>& t, int line, float hi) const {
        if (t.size() != 4)
            throw input_error(path_, line, "'" + t[0] + "' takes three numbers (R G B)");
        float c[3];
        for (int i = 0; i < 3; ++i) {
            c[i] = parse_float(t[1 + i], path_, line, t[0].c_str());
            if (c[i] < 0 || c[i] > hi)
                throw input_error(path_, line,
                                  "'" + t[0] + "' values must be in [0, " +
                                      (hi > 1e30f ? std::string("inf") : std::string("1")) + "]");
        }
        return {c[0], c[1], c[2]};
    }

    float number(const std::vector<std::string>& t, int line) const {
        if (t.size() != 2) throw input_error(path_, line, "'" + t[0] + "' takes one number");
        return parse_float(t[1], path_, line, t[0].c_str());
    }

    float number_in(const std::vector<std::string>& t, int line, float lo, float hi) const {
        float v = number(t, line);
        if (v < lo || v > hi)
            throw input_error(path_, line,
                              "'" + t[0] + "' must be in [" + format(lo) + ", " + format(hi) + "]");
        return v;
    }

    static std::string format(float v) {
        return std::to_string(static_cast<long>(v)); // the bounds are whole numbers
    }

    // Pm: metal from kMetalPm up; below it, not metal (with a warning
    // unless 0).
    float metallic(const std::vector<std::string>& t, int line) {
        float v = number_in(t, line, 0.0f, 1.0f);
        if (v >= kMetalPm) return v;
        if (v > 0)
            warnings_.add("Pm rounded", line,
                          "metallic Pm " + t[1] +
                              " is rounded to 0: materials are either metal or not, and metal "
                              "from Pm 0.5 up",
                          false);
        return 0.0f;
    }

    // d (opacity) and Tr = 1 - d: the surface is opaque whatever they say.
    void opacity(const std::vector<std::string>& t, int line) {
        float v = number_in(t, line, 0.0f, 1.0f);
        bool opaque = t[0] == "d" ? v == 1.0f : v == 0.0f;
        if (!opaque)
            warnings_.add(t[0], line,
                          "'" + t[0] + " " + t[1] +
                              "': partial transparency is not modelled and the surface renders "
                              "opaque (map_d makes a cut-out)",
                          false);
    }

    // A map's options (-bm 1, -s 1 1 1, ...) come before its file name,
    // the last token; none of them is read.
    std::string map_file(const std::vector<std::string>& t, int line) const {
        if (t.size() < 2) throw input_error(path_, line, "'" + t[0] + "' takes a file name");
        return t.back();
    }

    // The scene's index of the texture, read once per file and kind.
    u32 texture_index(const MtlTexture& t) {
        for (std::size_t i = 0; i < scene_.textures.size(); ++i)
            if (scene_.textures[i].file == t.map.file && scene_.textures[i].kind == t.kind)
                return static_cast<u32>(i);
        scene_.textures.push_back(
            load_texture(t.map.file, t.kind, path_ + ":" + std::to_string(t.map.line)));
        return static_cast<u32>(scene_.textures.size() - 1);
    }

    std::string path_;
    Scene& scene_;
    MtlMaterial cur_;
    bool open_ = false;
    FileWarnings warnings_;
};

} // namespace

void load_mtl(const std::string& path, Scene& scene) {
    MtlReader reader(path, scene);
    for_each_directive(path, "material", [&](int line, const std::vector<std::string>& t) {
        reader.directive(line, t);
    });
    reader.end();
}

} // namespace smallmlt
