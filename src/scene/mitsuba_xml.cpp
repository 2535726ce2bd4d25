#include "scene/mitsuba_xml.hpp"

#include "base/error.hpp"
#include "scene/text_parse.hpp"
#include "scene/texture.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

namespace smallmlt {

namespace {

const std::set<std::string> kObjectTags = {
    "scene",   "shape",   "bsdf",    "emitter", "sensor", "film",   "integrator",
    "texture", "sampler", "rfilter", "medium",  "phase",  "volume", "subsurface"};
const std::set<std::string> kPropertyTags = {"float",  "integer",   "boolean",  "string",
                                             "rgb",    "srgb",      "spectrum", "point",
                                             "vector", "transform", "color"};

// One file being read: its text (for line numbers) and parameters.
struct Source {
    std::string path;
    std::vector<std::size_t> line_starts;
    bool upgrade = false; // version < 2: camelCase names
    int line_of(std::ptrdiff_t offset) const {
        auto it = std::upper_bound(line_starts.begin(), line_starts.end(), std::size_t(offset));
        return int(it - line_starts.begin());
    }
    XmlWhere where(const pugi::xml_node& n) const { return {path, line_of(n.offset_debug())}; }
};

struct Reader {
    XmlDocument doc;
    std::map<std::string, std::string> params; // from <default>
    std::map<std::string, const XmlObject*> ids;
    struct PendingRef {
        XmlObject* parent;
        std::size_t slot;
        std::string id;
        XmlWhere where;
    };
    std::vector<PendingRef> refs;
    std::vector<std::string> include_stack;

    void read_file(const std::string& path, XmlObject& parent, const XmlWhere* from);
    void read_children(const pugi::xml_node& node, const Source& src, XmlObject& parent);
    void read_object(const pugi::xml_node& node, const Source& src, XmlObject& parent);
    XmlProperty read_property(const pugi::xml_node& node, const Source& src,
                              const std::string& parent_type);
    std::string attr(const pugi::xml_node& n, const char* name, const Source& src,
                     bool required = true);
};

std::string lower(std::string s) {
    for (char& c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// $name replaced from the parameters, longest names first.
std::string substitute(const std::string& value, const std::map<std::string, std::string>& params,
                       const XmlWhere& where) {
    if (value.find('$') == std::string::npos) return value;
    std::vector<const std::pair<const std::string, std::string>*> by_length;
    for (const auto& p : params)
        by_length.push_back(&p);
    std::stable_sort(by_length.begin(), by_length.end(),
                     [](auto* a, auto* b) { return a->first.size() > b->first.size(); });
    std::string out;
    for (std::size_t i = 0; i < value.size();) {
        if (value[i] != '$') {
            out += value[i++];
            continue;
        }
        bool done = false;
        for (auto* p : by_length)
            if (value.compare(i + 1, p->first.size(), p->first) == 0) {
                out += p->second;
                i += 1 + p->first.size();
                done = true;
                break;
            }
        if (!done) {
            std::size_t end = i + 1;
            while (end < value.size() &&
                   (std::isalnum(static_cast<unsigned char>(value[end])) || value[end] == '_'))
                ++end;
            throw input_error(where.file, where.line,
                              "parameter '" + value.substr(i, end - i) +
                                  "' has no value (no <default> gives one)");
        }
    }
    return out;
}

std::string Reader::attr(const pugi::xml_node& n, const char* name, const Source& src,
                         bool required) {
    pugi::xml_attribute a = n.attribute(name);
    if (!a) {
        if (required)
            throw input_error(src.path, src.line_of(n.offset_debug()),
                              "<" + std::string(n.name()) + "> needs the attribute '" + name + "'");
        return "";
    }
    return substitute(a.value(), params, src.where(n));
}

// Numbers of a value: separated by commas and/or white space.
std::vector<double> numbers(const std::string& text, const XmlWhere& w, const std::string& what) {
    std::vector<double> out;
    std::string tok;
    auto flush = [&] {
        if (tok.empty()) return;
        out.push_back(parse_float(tok, w.file, w.line, what.c_str()));
        tok.clear();
    };
    for (char c : text) {
        if (c == ',' || std::isspace(static_cast<unsigned char>(c)))
            flush();
        else
            tok += c;
    }
    flush();
    return out;
}

double one_number(const std::string& text, const XmlWhere& w, const std::string& what) {
    std::vector<double> v = numbers(text, w, what);
    if (v.size() != 1) throw input_error(w.file, w.line, what + " takes one number");
    return v[0];
}

Vec3 xyz_of(Reader& r, const pugi::xml_node& n, const Source& src, double fallback,
            const std::string& what) {
    XmlWhere w = src.where(n);
    std::string value = r.attr(n, "value", src, false);
    bool has_xyz = n.attribute("x") || n.attribute("y") || n.attribute("z");
    if (!value.empty()) {
        if (has_xyz)
            throw input_error(w.file, w.line, what + ": give 'value' or x, y, z, not both");
        std::vector<double> v = numbers(value, w, what);
        if (v.size() == 1) v.assign(3, v[0]);
        if (v.size() != 3) throw input_error(w.file, w.line, what + " takes 1 or 3 numbers");
        return {float(v[0]), float(v[1]), float(v[2])};
    }
    double c[3];
    const char* axes[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
        std::string s = r.attr(n, axes[i], src, false);
        c[i] = s.empty() ? fallback : one_number(s, w, what + " " + axes[i]);
    }
    return {float(c[0]), float(c[1]), float(c[2])};
}

Mat4 read_transform(Reader& r, const pugi::xml_node& node, const Source& src, XmlProperty& p) {
    Mat4 m;
    int ops = 0;
    for (pugi::xml_node op : node.children()) {
        if (op.type() != pugi::node_element) continue;
        const std::string tag = op.name();
        XmlWhere w = src.where(op);
        Mat4 t;
        if (tag == "translate") {
            Vec3 v = xyz_of(r, op, src, 0, "translate");
            t = Mat4::translate(v.x, v.y, v.z);
        } else if (tag == "scale") {
            Vec3 v = xyz_of(r, op, src, 1, "scale");
            t = Mat4::scale(v.x, v.y, v.z);
        } else if (tag == "rotate") {
            Vec3 axis = xyz_of(r, op, src, 0, "rotate axis");
            double angle = one_number(r.attr(op, "angle", src), w, "rotate angle");
            if (!(length(axis) > 0)) throw input_error(w.file, w.line, "rotate: the axis is zero");
            t = Mat4::rotate(axis.x, axis.y, axis.z, angle);
        } else if (tag == "matrix") {
            std::vector<double> v = numbers(r.attr(op, "value", src), w, "matrix");
            if (v.size() == 9) {
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        t.m[i][j] = v[3 * i + j];
            } else if (v.size() == 16) {
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j)
                        t.m[i][j] = v[4 * i + j];
                if (t.m[3][0] != 0 || t.m[3][1] != 0 || t.m[3][2] != 0 || t.m[3][3] != 1)
                    throw input_error(w.file, w.line,
                                      "matrix: the last row must be 0 0 0 1 (projective "
                                      "transforms are not read)");
            } else {
                throw input_error(w.file, w.line, "matrix takes 9 or 16 numbers (row by row)");
            }
        } else if (tag == "lookat" || (src.upgrade && tag == "lookAt")) {
            auto vec = [&](const char* name, bool required) -> Vec3 {
                std::string s = r.attr(op, name, src, required);
                if (s.empty()) return {0, 0, 0};
                std::vector<double> v = numbers(s, w, std::string("lookat ") + name);
                if (v.size() != 3)
                    throw input_error(w.file, w.line,
                                      std::string("lookat ") + name + " takes 3 numbers");
                return {float(v[0]), float(v[1]), float(v[2])};
            };
            Vec3 origin = vec("origin", true), target = vec("target", true), up = vec("up", false);
            if (!(length(up) > 0))
                throw input_error(w.file, w.line,
                                  "lookat without 'up' (Mitsuba picks an arbitrary one; give it)");
            if (!Mat4::look_at(origin, target, up, t))
                throw input_error(
                    w.file, w.line,
                    "lookat: origin and target coincide, or up is parallel to the view");
            p.is_lookat = ops == 0;
            p.lookat[0] = origin, p.lookat[1] = target, p.lookat[2] = up;
        } else {
            throw input_error(
                w.file, w.line,
                "<" + tag + "> is not a transform (translate, rotate, scale, matrix, lookat)");
        }
        m = t * m;
        if (ops++ > 0) p.is_lookat = false;
    }
    return m;
}

XmlProperty Reader::read_property(const pugi::xml_node& node, const Source& src,
                                  const std::string& parent_type) {
    XmlProperty p;
    p.tag = node.name();
    p.where = src.where(node);
    p.name = attr(node, "name", src);
    if (src.upgrade) {
        p.name = xml_snake_case(p.name);
        if (parent_type == "diffuse" && p.name == "diffuse_reflectance") p.name = "reflectance";
    }
    const std::string what = "<" + p.tag + " name=\"" + p.name + "\">";
    const XmlWhere& w = p.where;
    if (p.tag == "float") {
        p.numbers = {one_number(attr(node, "value", src), w, what)};
    } else if (p.tag == "integer") {
        p.numbers = {double(parse_int(attr(node, "value", src), w.file, w.line, what.c_str()))};
    } else if (p.tag == "boolean") {
        std::string v = lower(attr(node, "value", src));
        if (v != "true" && v != "false")
            throw input_error(w.file, w.line, what + " must be true or false");
        p.text = v;
    } else if (p.tag == "string") {
        p.text = attr(node, "value", src);
    } else if (p.tag == "rgb" || p.tag == "srgb" || p.tag == "color") {
        if (p.tag != "rgb" && !src.upgrade)
            throw input_error(w.file, w.line,
                              "<" + p.tag + "> is a tag of version 0.6 files (version 3: <rgb>)");
        std::string v = attr(node, "value", src);
        std::vector<double> c;
        if (!v.empty() && v[0] == '#') {
            if (v.size() != 7 ||
                v.find_first_not_of("0123456789abcdefABCDEF", 1) != std::string::npos)
                throw input_error(w.file, w.line, what + ": '" + v + "' is not #RRGGBB");
            for (int i = 0; i < 3; ++i)
                c.push_back(std::strtol(v.substr(1 + 2 * i, 2).c_str(), nullptr, 16) / 255.0);
            if (p.tag == "rgb") p.tag = "srgb"; // #RRGGBB is gamma encoded
        } else {
            c = numbers(v, w, what);
            if (c.size() == 1) c.assign(3, c[0]);
            if (c.size() != 3) throw input_error(w.file, w.line, what + " takes 1 or 3 numbers");
        }
        if (p.tag == "srgb")
            for (double& x : c)
                x = srgb_to_linear(x);
        p.tag = "rgb";
        p.numbers = c;
    } else if (p.tag == "spectrum") {
        if (node.attribute("filename"))
            throw input_error(
                w.file, w.line,
                what + ": spectra from files are not read (give a uniform value or <rgb>)");
        std::string v = attr(node, "value", src);
        if (v.find(':') != std::string::npos)
            throw input_error(w.file, w.line,
                              what + ": a spectrum of wavelength:value pairs is not read (give a "
                                     "uniform value or <rgb>)");
        std::vector<double> c = numbers(v, w, what);
        if (c.size() != 1)
            throw input_error(w.file, w.line,
                              what + ": only uniform spectra (one value) are read; give <rgb>");
        p.numbers = c;
    } else if (p.tag == "point" || p.tag == "vector") {
        Vec3 v = xyz_of(*this, node, src, 0, what);
        if (!node.attribute("value") &&
            !(node.attribute("x") && node.attribute("y") && node.attribute("z")))
            throw input_error(w.file, w.line, what + " needs x, y and z (or value)");
        p.numbers = {v.x, v.y, v.z};
    } else { // transform
        p.transform = read_transform(*this, node, src, p);
    }
    return p;
}

void Reader::read_object(const pugi::xml_node& node, const Source& src, XmlObject& parent) {
    doc.objects.emplace_back();
    XmlObject& o = doc.objects.back();
    o.tag = node.name();
    o.where = src.where(node);
    o.type = attr(node, "type", src);
    o.id = attr(node, "id", src, false);
    o.name = attr(node, "name", src, false);
    if (src.upgrade) o.name = xml_snake_case(o.name);
    if (!o.id.empty()) {
        if (ids.count(o.id))
            throw input_error(o.where.file, o.where.line,
                              "id '" + o.id + "' is used twice (first at " +
                                  ids[o.id]->where.str() + ")");
        ids[o.id] = &o;
    }
    parent.children.push_back(&o);
    read_children(node, src, o);
}

void Reader::read_children(const pugi::xml_node& node, const Source& src, XmlObject& parent) {
    for (pugi::xml_node n : node.children()) {
        if (n.type() != pugi::node_element) continue;
        const std::string tag = n.name();
        XmlWhere w = src.where(n);
        if (tag == "default") {
            std::string name = n.attribute("name").value();
            if (name.empty()) throw input_error(w.file, w.line, "<default> needs a name");
            if (!params.count(name)) params[name] = attr(n, "value", src);
        } else if (tag == "include") {
            std::string file = attr(n, "filename", src);
            std::string path = file.size() && file[0] == '/' ? file : dir_of(src.path) + file;
            read_file(path, parent, &w);
        } else if (tag == "ref") {
            refs.push_back({&parent, parent.children.size(), attr(n, "id", src), w});
            parent.children.push_back(nullptr);
        } else if (kObjectTags.count(tag) && tag != "scene") {
            read_object(n, src, parent);
        } else if (kPropertyTags.count(tag)) {
            parent.properties.push_back(read_property(n, src, parent.type));
        } else {
            throw input_error(w.file, w.line,
                              "<" + tag +
                                  "> is not read (objects: shape, bsdf, emitter, sensor, "
                                  "film, integrator, texture, ...; properties: float, "
                                  "integer, boolean, string, rgb, spectrum, point, "
                                  "vector, transform; default, include, ref)");
        }
    }
}

void Reader::read_file(const std::string& path, XmlObject& parent, const XmlWhere* from) {
    if (std::find(include_stack.begin(), include_stack.end(), path) != include_stack.end())
        throw input_error(from->file, from->line, "'" + path + "' includes itself");
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        if (from) throw input_error(from->file, from->line, "cannot open included file " + path);
        throw InputError(path + ": cannot open scene file");
    }
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    Source src;
    src.path = path;
    src.line_starts.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') src.line_starts.push_back(i + 1);
    pugi::xml_document xml;
    pugi::xml_parse_result res = xml.load_buffer(text.data(), text.size());
    if (!res)
        throw input_error(path, src.line_of(res.offset),
                          std::string("not well-formed XML: ") + res.description());
    pugi::xml_node root = xml.document_element();
    if (std::string(root.name()) != "scene")
        throw input_error(path, src.line_of(root.offset_debug()),
                          "the root element is <" + std::string(root.name()) + ">, not <scene>");
    std::string version = root.attribute("version").value();
    std::vector<double> parts;
    {
        std::string tok;
        for (char c : version + ".") {
            if (c == '.') {
                if (tok.empty() || tok.find_first_not_of("0123456789") != std::string::npos) {
                    parts.clear();
                    break;
                }
                parts.push_back(std::atof(tok.c_str()));
                tok.clear();
            } else {
                tok += c;
            }
        }
    }
    if (parts.size() != 3)
        throw input_error(path, src.line_of(root.offset_debug()),
                          "<scene> needs version=\"X.Y.Z\" (0.5.0, 0.6.0 or 3.0.0)");
    src.upgrade = parts[0] < 2;
    include_stack.push_back(path);
    read_children(root, src, parent);
    include_stack.pop_back();
}

void check_tag(const XmlProperty& p, std::initializer_list<const char*> tags, const char* what) {
    for (const char* t : tags)
        if (p.tag == t) {
            p.read = true;
            return;
        }
    throw input_error(p.where.file, p.where.line,
                      "'" + p.name + "' is <" + p.tag + ">; it must be " + what);
}

} // namespace

const XmlProperty* XmlObject::find(const std::string& prop_name) const {
    const XmlProperty* found = nullptr;
    for (const XmlProperty& p : properties)
        if (p.name == prop_name) {
            if (found)
                throw input_error(p.where.file, p.where.line,
                                  "'" + prop_name + "' given twice (first at " +
                                      found->where.str() + ")");
            found = &p;
        }
    return found;
}

std::string XmlObject::what() const {
    return tag + " '" + type + "' (" + where.str() + ")";
}

XmlDocument read_mitsuba_xml(const std::string& path) {
    Reader r;
    r.doc.objects.emplace_back();
    XmlObject& root = r.doc.objects.front();
    root.tag = "scene";
    root.where = {path, 1};
    r.read_file(path, root, nullptr);
    for (const Reader::PendingRef& ref : r.refs) {
        auto it = r.ids.find(ref.id);
        if (it == r.ids.end())
            throw input_error(ref.where.file, ref.where.line,
                              "<ref id=\"" + ref.id + "\"> names no object");
        ref.parent->children[ref.slot] = it->second;
    }
    return std::move(r.doc);
}

double xml_float(const XmlObject& o, const std::string& name, double fallback) {
    const XmlProperty* p = o.find(name);
    if (!p) return fallback;
    check_tag(*p, {"float", "integer"}, "a <float>");
    return p->numbers[0];
}

long xml_int(const XmlObject& o, const std::string& name, long fallback) {
    const XmlProperty* p = o.find(name);
    if (!p) return fallback;
    check_tag(*p, {"integer"}, "an <integer>");
    return long(p->numbers[0]);
}

bool xml_bool(const XmlObject& o, const std::string& name, bool fallback) {
    const XmlProperty* p = o.find(name);
    if (!p) return fallback;
    check_tag(*p, {"boolean"}, "a <boolean>");
    return p->text == "true";
}

std::string xml_string(const XmlObject& o, const std::string& name, const std::string& fallback) {
    const XmlProperty* p = o.find(name);
    if (!p) return fallback;
    check_tag(*p, {"string"}, "a <string>");
    return p->text;
}

Vec3 xml_color(const XmlObject& o, const std::string& name, Vec3 fallback) {
    const XmlProperty* p = o.find(name);
    if (!p) return fallback;
    check_tag(*p, {"rgb", "spectrum", "float"}, "<rgb>, a uniform <spectrum> or a <float>");
    if (p->numbers.size() == 1) {
        float v = float(p->numbers[0]);
        return {v, v, v};
    }
    return {float(p->numbers[0]), float(p->numbers[1]), float(p->numbers[2])};
}

Vec3 xml_point(const XmlObject& o, const std::string& name, Vec3 fallback) {
    const XmlProperty* p = o.find(name);
    if (!p) return fallback;
    check_tag(*p, {"point", "vector"}, "a <point>");
    return {float(p->numbers[0]), float(p->numbers[1]), float(p->numbers[2])};
}

Mat4 xml_transform(const XmlObject& o, const std::string& name) {
    const XmlProperty* p = o.find(name);
    if (!p) return Mat4();
    check_tag(*p, {"transform"}, "a <transform>");
    return p->transform;
}

void xml_warn_unread(const XmlObject& o, std::vector<std::string>& warnings) {
    for (const XmlProperty& p : o.properties)
        if (!p.read)
            warnings.push_back(p.where.str() + ": warning: '" + p.name + "' of " + o.tag + " '" +
                               o.type + "' is not read (ignored)");
}

std::string xml_snake_case(const std::string& name) {
    std::string out;
    auto is_lower = [](char c) { return c >= 'a' && c <= 'z'; };
    auto is_upper = [](char c) { return c >= 'A' && c <= 'Z'; };
    for (std::size_t i = 0; i < name.size(); ++i) {
        if (i > 0 && is_upper(name[i]) && is_lower(name[i - 1])) {
            out += '_';
            while (i < name.size() && is_upper(name[i]))
                out += char(name[i++] - 'A' + 'a');
            --i;
        } else {
            out += name[i];
        }
    }
    return out;
}

} // namespace smallmlt
