// The PLY reader of Mitsuba's ply shape (doc/scene-format.md, "Mitsuba
// scenes"): ASCII and binary of either byte order, format 1.0. The vertex
// element gives x, y, z and optionally nx, ny, nz and texture coordinates
// (u, v; s, t; texture_u, texture_v; or texture_s, texture_t); the face
// element a list vertex_indices (or vertex_index) of 3 or more vertices,
// fanned into triangles. Other elements and properties are read past.
#include "base/error.hpp"
#include "scene/scene.hpp"
#include "scene/text_parse.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace smallmlt {

namespace {

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::F32;
    bool list = false;
    PlyType count_type = PlyType::U8;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    int line = 0; // of its header line
    std::vector<PlyProperty> props;
};

enum class PlyFormat { Ascii, BinaryLittle, BinaryBig };

bool ply_type(const std::string& s, PlyType* t) {
    static const struct {
        const char* a;
        const char* b;
        PlyType t;
    } names[] = {{"char", "int8", PlyType::I8},      {"uchar", "uint8", PlyType::U8},
                 {"short", "int16", PlyType::I16},   {"ushort", "uint16", PlyType::U16},
                 {"int", "int32", PlyType::I32},     {"uint", "uint32", PlyType::U32},
                 {"float", "float32", PlyType::F32}, {"double", "float64", PlyType::F64}};
    for (const auto& n : names)
        if (s == n.a || s == n.b) {
            *t = n.t;
            return true;
        }
    return false;
}

bool is_integer(PlyType t) {
    return t != PlyType::F32 && t != PlyType::F64;
}

// The values of the body, in order, from ASCII tokens or binary words.
class PlyValues {
  public:
    PlyValues(std::istream& in, PlyFormat format, const std::string& path, int line)
        : in_(in), format_(format), path_(path), line_(line) {}

    // The next value, read as `type`; `what` names it for errors.
    double next(PlyType type, const std::string& what) {
        return format_ == PlyFormat::Ascii ? next_token(type, what) : next_binary(type, what);
    }

    // Where the reader is, for messages: the ASCII line, or for binary data
    // the header line of the element being read.
    int line() const { return line_; }
    void set_element_line(int line) {
        if (format_ != PlyFormat::Ascii) line_ = line;
    }

  private:
    double next_token(PlyType type, const std::string& what) {
        while (pos_ >= tokens_.size()) {
            std::string text;
            if (!std::getline(in_, text))
                throw input_error(path_, line_, "the file ends inside " + what);
            ++line_;
            tokens_ = split_tokens(text);
            pos_ = 0;
        }
        const std::string& tok = tokens_[pos_++];
        if (is_integer(type)) return double(parse_int(tok, path_, line_, what.c_str()));
        return double(parse_float(tok, path_, line_, what.c_str()));
    }

    double next_binary(PlyType type, const std::string& what) {
        static const int sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
        const int n = sizes[int(type)];
        unsigned char b[8];
        if (!in_.read(reinterpret_cast<char*>(b), n))
            throw input_error(path_, line_, "the file ends inside " + what);
        const bool little = format_ == PlyFormat::BinaryLittle;
        std::uint64_t u = 0;
        for (int i = 0; i < n; ++i)
            u |= std::uint64_t(b[little ? i : n - 1 - i]) << (8 * i);
        switch (type) {
        case PlyType::I8:
            return double(std::int8_t(u));
        case PlyType::U8:
            return double(u);
        case PlyType::I16:
            return double(std::int16_t(u));
        case PlyType::U16:
            return double(u);
        case PlyType::I32:
            return double(std::int32_t(u));
        case PlyType::U32:
            return double(u);
        case PlyType::F32: {
            std::uint32_t w = std::uint32_t(u);
            float f;
            std::memcpy(&f, &w, 4);
            return double(f);
        }
        case PlyType::F64: {
            double d;
            std::memcpy(&d, &u, 8);
            return d;
        }
        }
        return 0;
    }

    std::istream& in_;
    PlyFormat format_;
    std::string path_;
    int line_;
    std::vector<std::string> tokens_;
    std::size_t pos_ = 0;
};

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    int end_line = 0; // of end_header
};

PlyHeader read_header(std::istream& in, const std::string& path) {
    PlyHeader h;
    std::string text;
    int line = 0;
    bool has_format = false;
    while (std::getline(in, text)) {
        ++line;
        if (!text.empty() && text.back() == '\r') text.pop_back();
        std::istringstream ss(text);
        std::string word;
        ss >> word;
        if (line == 1) {
            if (word != "ply") throw input_error(path, 1, "not a PLY file (no 'ply' line)");
            continue;
        }
        std::vector<std::string> t;
        for (std::string w; ss >> w;)
            t.push_back(w);
        if (word == "comment" || word == "obj_info" || word.empty()) continue;
        if (word == "end_header") {
            if (!has_format) throw input_error(path, line, "no 'format' line before end_header");
            h.end_line = line;
            return h;
        }
        if (word == "format") {
            if (t.size() != 2 || t[1] != "1.0")
                throw input_error(path, line, "'format' takes a format and version 1.0");
            if (t[0] == "ascii")
                h.format = PlyFormat::Ascii;
            else if (t[0] == "binary_little_endian")
                h.format = PlyFormat::BinaryLittle;
            else if (t[0] == "binary_big_endian")
                h.format = PlyFormat::BinaryBig;
            else
                throw input_error(path, line,
                                  "format '" + t[0] +
                                      "' is not read (ascii, binary_little_endian and "
                                      "binary_big_endian are)");
            has_format = true;
        } else if (word == "element") {
            if (t.size() != 2) throw input_error(path, line, "'element' takes a name and a count");
            long n = parse_int(t[1], path, line, "element count");
            if (n < 0) throw input_error(path, line, "element count is negative");
            h.elements.push_back({t[0], std::uint64_t(n), line, {}});
        } else if (word == "property") {
            if (h.elements.empty())
                throw input_error(path, line, "'property' before any 'element'");
            PlyProperty p;
            bool ok;
            if (!t.empty() && t[0] == "list") {
                p.list = true;
                ok = t.size() == 4 && ply_type(t[1], &p.count_type) && is_integer(p.count_type) &&
                     ply_type(t[2], &p.type);
                if (ok) p.name = t[3];
            } else {
                ok = t.size() == 2 && ply_type(t[0], &p.type);
                if (ok) p.name = t[1];
            }
            if (!ok)
                throw input_error(path, line,
                                  "'property' takes a type and a name, or 'list', an integer "
                                  "count type, a type and a name");
            h.elements.back().props.push_back(p);
        } else {
            throw input_error(path, line, "unknown PLY header line '" + word + "'");
        }
    }
    throw input_error(path, line, "the file ends before 'end_header'");
}

// Column of `name` among the element's scalar properties, or -1.
int column(const PlyElement& e, std::initializer_list<const char*> names) {
    for (const char* n : names)
        for (std::size_t i = 0; i < e.props.size(); ++i)
            if (!e.props[i].list && e.props[i].name == n) return int(i);
    return -1;
}

struct PlyVertex {
    Vec3 p, n;
    float uv[2] = {0, 0};
};

} // namespace

void load_ply_geometry(const std::string& path, const std::string& where, std::uint32_t material,
                       Scene& scene) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(where + ": cannot open PLY file " + path);
    const PlyHeader h = read_header(in, path);
    PlyValues values(in, h.format, path, h.end_line);
    std::vector<PlyVertex> verts;
    bool has_normals = false, has_faces = false;
    const std::size_t first = scene.triangles.size();
    for (const PlyElement& e : h.elements) {
        values.set_element_line(e.line);
        const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
        int cx = -1, cy = -1, cz = -1, cn[3] = {-1, -1, -1}, cu = -1, cv = -1, list = -1;
        if (is_vertex) {
            cx = column(e, {"x"}), cy = column(e, {"y"}), cz = column(e, {"z"});
            if (cx < 0 || cy < 0 || cz < 0)
                throw input_error(path, e.line, "element 'vertex' needs properties x, y and z");
            cn[0] = column(e, {"nx"}), cn[1] = column(e, {"ny"}), cn[2] = column(e, {"nz"});
            has_normals = cn[0] >= 0 && cn[1] >= 0 && cn[2] >= 0;
            cu = column(e, {"u", "s", "texture_u", "texture_s"});
            cv = column(e, {"v", "t", "texture_v", "texture_t"});
        }
        if (is_face) {
            for (std::size_t i = 0; i < e.props.size(); ++i)
                if (e.props[i].list &&
                    (e.props[i].name == "vertex_indices" || e.props[i].name == "vertex_index"))
                    list = int(i);
            if (list < 0)
                throw input_error(path, e.line,
                                  "element 'face' needs a list property 'vertex_indices'");
            if (!is_integer(e.props[std::size_t(list)].type))
                throw input_error(path, e.line, "face indices must be integers");
            has_faces = true;
        }
        for (std::uint64_t item = 0; item < e.count; ++item) {
            const std::string what = e.name + " " + std::to_string(item);
            PlyVertex v;
            double s[3] = {0, 0, 0}, n[3] = {0, 0, 0};
            std::vector<std::uint32_t> face;
            for (std::size_t c = 0; c < e.props.size(); ++c) {
                const PlyProperty& p = e.props[c];
                if (p.list) {
                    double k = values.next(p.count_type, what);
                    if (k < 0) throw input_error(path, values.line(), what + ": negative count");
                    for (double j = 0; j < k; ++j) {
                        double x = values.next(p.type, what);
                        if (int(c) != list) continue;
                        if (x < 0 || x >= double(verts.size()))
                            throw input_error(path, values.line(),
                                              what + ": vertex index " + std::to_string(long(x)) +
                                                  " is out of range (" +
                                                  std::to_string(verts.size()) + " vertices)");
                        face.push_back(std::uint32_t(x));
                    }
                    continue;
                }
                double x = values.next(p.type, what);
                if (!std::isfinite(x))
                    throw input_error(path, values.line(), what + ": a value is not finite");
                int ci = int(c);
                for (int a = 0; a < 3; ++a) {
                    if (ci == (a == 0 ? cx : a == 1 ? cy : cz)) s[a] = x;
                    if (ci == cn[a]) n[a] = x;
                }
                if (ci == cu) v.uv[0] = float(x);
                if (ci == cv) v.uv[1] = float(x);
            }
            if (is_vertex) {
                v.p = {float(s[0]), float(s[1]), float(s[2])};
                if (has_normals) {
                    double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                    if (!(len > 0))
                        throw input_error(path, values.line(), what + ": normal has zero length");
                    v.n = {float(n[0] / len), float(n[1] / len), float(n[2] / len)};
                }
                verts.push_back(v);
            }
            if (!is_face) continue;
            if (face.size() < 3)
                throw input_error(path, values.line(), what + ": a face needs at least 3 vertices");
            for (std::size_t k = 1; k + 1 < face.size(); ++k) {
                const PlyVertex* fv[3] = {&verts[face[0]], &verts[face[k]], &verts[face[k + 1]]};
                SceneTriangle tri;
                tri.material = material;
                for (int j = 0; j < 3; ++j) {
                    tri.v[j] = fv[j]->p;
                    tri.n[j] = fv[j]->n;
                    tri.uv[j][0] = fv[j]->uv[0];
                    tri.uv[j][1] = fv[j]->uv[1];
                }
                if (!(length(cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0])) > 0)) {
                    ++scene.dropped_degenerate;
                    continue;
                }
                tri.smooth = has_normals;
                if (!has_normals) {
                    const Vec3 flat = tri.flat_normal();
                    for (Vec3& nn : tri.n)
                        nn = flat;
                }
                scene.triangles.push_back(tri);
            }
        }
    }
    if (!has_faces) throw input_error(path, h.end_line, "no element 'face': the file has no mesh");
    if (scene.triangles.size() == first)
        throw InputError(where + ": PLY file " + path + " has no triangle of non-zero area");
}

} // namespace smallmlt
