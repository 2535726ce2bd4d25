// Mitsuba scene files: the XML reader (names, defaults, includes, refs,
// values), transforms, shapes, BSDFs, sensor and integrator against
// hand-computed values, and every error with its file and line.
#include "base/error.hpp"
#include "render/mlt.hpp"
#include "scene/device_scene.hpp"
#include "scene/material.hpp"
#include "scene/mitsuba_bsdfs.hpp"
#include "scene/mitsuba_shapes.hpp"
#include "scene/mitsuba_xml.hpp"
#include "scene/texture.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <cmath>
#include <cstring>

using namespace smallmlt;

namespace {

const char* kSensor = R"(<sensor type="perspective">
        <float name="fov" value="40"/>
        <string name="fov_axis" value="y"/>
        <transform name="to_world"><lookat origin="0, 1, 3.4" target="0, 1, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="24"/>
            <rfilter type="box"/></film>
    </sensor>)";
const char* kLamp = R"(<shape type="rectangle">
        <transform name="to_world"><rotate x="1" angle="90"/><translate y="2"/></transform>
        <emitter type="area"><rgb name="radiance" value="10"/></emitter>
    </shape>)";

std::string scene_xml(const std::string& body, const std::string& version = "3.0.0") {
    return "<scene version=\"" + version + "\">\n    " + kSensor + "\n    " + kLamp + "\n    " +
           body + "\n</scene>\n";
}

// Writes `xml` (and `extra` files: name, text) into a fresh directory and
// loads it.
Scene load(const std::string& dir_name, const std::string& xml,
           const std::vector<std::pair<std::string, std::string>>& extra = {}) {
    std::string dir = test::scratch_dir("mitsuba-" + dir_name);
    for (const auto& f : extra)
        test::write_file(dir + "/" + f.first, f.second);
    test::write_file(dir + "/s.xml", xml);
    return load_scene(dir + "/s.xml");
}

// The error of loading, relative to the directory ("s.xml:3: ..."), or "".
std::string load_error(const std::string& dir_name, const std::string& xml,
                       const std::vector<std::pair<std::string, std::string>>& extra = {}) {
    const std::string msg = test::input_error_of([&] { load(dir_name, xml, extra); });
    const std::string key = "mitsuba-" + dir_name + "/";
    const std::size_t at = msg.find(key);
    return at == std::string::npos ? msg : msg.substr(at + key.size());
}

double area(const Scene& s, std::size_t first = 0) {
    double a = 0;
    for (std::size_t i = first; i < s.triangles.size(); ++i) {
        const SceneTriangle& t = s.triangles[i];
        a += 0.5 * length(cross(t.v[1] - t.v[0], t.v[2] - t.v[0]));
    }
    return a;
}

void expect_vec(Vec3 got, Vec3 want, double tol, const char* what) {
    EXPECT_NEAR(got.x, want.x, tol) << what;
    EXPECT_NEAR(got.y, want.y, tol) << what;
    EXPECT_NEAR(got.z, want.z, tol) << what;
}

} // namespace

TEST(MitsubaXml, SnakeCaseIsMitsubasUpgradeRule) {
    EXPECT_EQ(xml_snake_case("toWorld"), "to_world");
    EXPECT_EQ(xml_snake_case("intIOR"), "int_ior");
    EXPECT_EQ(xml_snake_case("fovAxis"), "fov_axis");
    EXPECT_EQ(xml_snake_case("maxDepth"), "max_depth");
    EXPECT_EQ(xml_snake_case("specularReflectance"), "specular_reflectance");
    EXPECT_EQ(xml_snake_case("alphaU"), "alpha_u");
    EXPECT_EQ(xml_snake_case("color0"), "color0");
    EXPECT_EQ(xml_snake_case("Upper"), "Upper");
    EXPECT_EQ(xml_snake_case("to_world"), "to_world");
}

TEST(MitsubaTransform, EachOperationAndTheirOrder) {
    Vec3 p{1, 2, 3};
    expect_vec(Mat4::translate(1, -2, 0.5).point(p), {2, 0, 3.5}, 1e-6, "translate");
    expect_vec(Mat4::translate(1, -2, 0.5).vector(p), p, 1e-6, "translate leaves vectors");
    expect_vec(Mat4::scale(2, 3, -1).point(p), {2, 6, -3}, 1e-6, "scale");
    expect_vec(Mat4::rotate(0, 0, 1, 90).point({1, 0, 0}), {0, 1, 0}, 1e-6, "rotate z 90");
    expect_vec(Mat4::rotate(1, 0, 0, 90).point({0, 1, 0}), {0, 0, 1}, 1e-6, "rotate x 90");
    expect_vec(Mat4::rotate(0, 2, 0, 90).point({0, 0, 1}), {1, 0, 0}, 1e-6, "rotate y 90");
    expect_vec(Mat4::rotate(1, 1, 1, 120).point({1, 0, 0}), {0, 1, 0}, 1e-6, "axis (1,1,1)");
    // scale first, then translate: translate * scale.
    expect_vec((Mat4::translate(1, 0, 0) * Mat4::scale(2, 2, 2)).point(p), {3, 4, 6}, 1e-6,
               "composition");
    Mat4 la;
    ASSERT_TRUE(Mat4::look_at({1, 2, 3}, {1, 2, 0}, {0, 1, 0}, la));
    expect_vec(la.point({0, 0, 0}), {1, 2, 3}, 1e-6, "lookat origin");
    expect_vec(la.vector({0, 0, 1}), {0, 0, -1}, 1e-6, "lookat +z looks at the target");
    expect_vec(la.vector({0, 1, 0}), {0, 1, 0}, 1e-6, "lookat +y is up");
    expect_vec(la.vector({1, 0, 0}), {-1, 0, 0}, 1e-6, "lookat +x = cross(up, dir)");
    EXPECT_FALSE(Mat4::look_at({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, la)) << "up parallel to the view";
    // Normals: the inverse transpose.
    expect_vec(normalize(Mat4::scale(1, 4, 1).normal(normalize(Vec3{1, 1, 0}))),
               normalize(Vec3{4, 1, 0}), 1e-6, "normal under a scale");
    expect_vec(Mat4::scale(-1, 1, 1).normal({1, 0, 0}), {-1, 0, 0}, 1e-6, "normal under a mirror");
}

TEST(MitsubaXml, TransformElementsAreReadInOrder) {
    Scene s = load("transform", scene_xml(R"(<shape type="rectangle">
        <transform name="to_world">
            <scale value="2"/>
            <rotate x="0" y="0" z="1" angle="90"/>
            <translate x="1" y="2" z="3"/>
            <matrix value="1 0 0 10  0 1 0 20  0 0 1 30  0 0 0 1"/>
        </transform>
    </shape>)"));
    // The corner (1, 1, 0): scaled to (2, 2), turned to (-2, 2), moved to
    // (-1, 4, 3), then by the matrix's translation (10, 20, 30).
    const SceneTriangle& t = s.triangles[2];
    expect_vec(t.v[2], {9, 24, 33}, 1e-5, "the corner (1, 1, 0)");
    EXPECT_NEAR(area(s, 2), 16, 1e-4);
}

TEST(MitsubaShapes, AnalyticShapesHaveTheirExactAreasAndOutwardNormals) {
    struct Row {
        const char* xml;
        std::size_t triangles;
        double area;
    } rows[] = {
        {R"(<shape type="rectangle"/>)", 2, 4},
        {R"(<shape type="cube"/>)", 12, 24},
        {R"(<shape type="disk"/>)", kCurveSegments, M_PI},
        {R"(<shape type="sphere"><float name="radius" value="0.5"/><point name="center" x="1" y="2" z="3"/></shape>)",
         std::size_t(2 * kCurveSegments * (kSphereRings - 1)), M_PI},
    };
    for (const Row& r : rows) {
        Scene s = load("area", scene_xml(r.xml));
        const std::size_t first = 2; // after the lamp
        EXPECT_EQ(s.triangles.size() - first, r.triangles) << r.xml;
        EXPECT_NEAR(area(s, first), r.area, 1e-5 * r.area) << r.xml;
        // Outward: the geometric normal points away from the shape's centre.
        Vec3 centre{0, 0, 0};
        if (std::string(r.xml).find("sphere") != std::string::npos) centre = {1, 2, 3};
        for (std::size_t i = first; i < s.triangles.size(); ++i) {
            const SceneTriangle& t = s.triangles[i];
            Vec3 g = cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
            Vec3 mid = (t.v[0] + t.v[1] + t.v[2]) * (1.0f / 3) - centre;
            if (std::string(r.xml).find("rectangle") != std::string::npos ||
                std::string(r.xml).find("disk") != std::string::npos)
                EXPECT_GT(g.z, 0) << r.xml;
            else
                EXPECT_GT(dot(g, mid), 0) << r.xml << " triangle " << i;
        }
    }
}

TEST(MitsubaShapes, SphereIsWithinItsToleranceAndShadesWithItsOwnNormals) {
    Scene s = load("sphere",
                   scene_xml(R"(<shape type="sphere"><float name="radius" value="2"/></shape>)"));
    double worst = 0;
    for (std::size_t i = 2; i < s.triangles.size(); ++i) {
        const SceneTriangle& t = s.triangles[i];
        ASSERT_TRUE(t.smooth);
        for (int k = 0; k < 3; ++k) {
            worst = std::max(worst, std::abs(length(t.v[k]) - 2.0) / 2);
            expect_vec(t.n[k], normalize(t.v[k]), 1e-5, "the sphere's own normal");
        }
        Vec3 mid = (t.v[0] + t.v[1] + t.v[2]) * (1.0f / 3);
        worst = std::max(worst, std::abs(length(mid) - 2.0) / 2);
    }
    EXPECT_LT(worst, 2e-3) << "distance from the sphere, as a fraction of the radius";
}

TEST(MitsubaShapes, FlipNormalsReversesTheWinding) {
    Scene s =
        load("flip",
             scene_xml(
                 R"(<shape type="rectangle"><boolean name="flip_normals" value="true"/></shape>)"));
    for (std::size_t i = 2; i < 4; ++i) {
        const SceneTriangle& t = s.triangles[i];
        EXPECT_LT(cross(t.v[1] - t.v[0], t.v[2] - t.v[0]).z, 0);
        EXPECT_FLOAT_EQ(t.n[0].z, -1);
    }
}

TEST(MitsubaShapes, ObjIgnoresMaterialsAndComputesAngleWeightedNormals) {
    // Two triangles meeting at a right angle along the x axis: the shared
    // vertices' normal is the bisector; face_normals keeps them flat.
    const char* obj = "mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 0 0 -1\nv 0 2 0\nvt 0 0.25\nvt 1 0.25\n"
                      "vt 0 1\nusemtl nothing\nf 1/1 2/2 3/3\nf 1/1 2/2 4/3\n";
    Scene s = load(
        "obj", scene_xml(R"(<shape type="obj"><string name="filename" value="m.obj"/></shape>)"),
        {{"m.obj", obj}});
    ASSERT_EQ(s.triangles.size(), 4u);
    const SceneTriangle& a = s.triangles[2];
    EXPECT_TRUE(a.smooth);
    expect_vec(a.n[0], normalize(Vec3{0, 1, 1}), 1e-6, "shared vertex: the bisector");
    // (1, 0, 0): 45 degrees in the first face, atan 2 in the second.
    expect_vec(a.n[1], normalize(Vec3{0, float(M_PI / 4), float(std::atan(2.0))}), 1e-6,
               "angle-weighted");
    expect_vec(a.n[2], {0, 1, 0}, 1e-6, "unshared vertex: its face's normal");
    EXPECT_FLOAT_EQ(a.uv[0][1], 0.25f) << "flip_tex_coords (default): the file's v as read";
    Scene f =
        load("obj-flat", scene_xml(R"(<shape type="obj"><string name="filename" value="m.obj"/>
        <boolean name="face_normals" value="true"/><boolean name="flip_tex_coords" value="false"/></shape>)"),
             {{"m.obj", obj}});
    EXPECT_FALSE(f.triangles[2].smooth);
    expect_vec(f.triangles[2].n[0], {0, 1, 0}, 1e-6, "face_normals");
    EXPECT_FLOAT_EQ(f.triangles[2].uv[0][1], 0.75f) << "without the flip";
}

TEST(MitsubaBsdfs, ParametersAndDefaults) {
    std::vector<std::string> w;
    auto bsdf = [&](const std::string& xml) {
        Scene s = load("bsdf", scene_xml("<shape type=\"rectangle\">" + xml + "</shape>"));
        w = s.warnings;
        return s.materials[s.triangles.back().material];
    };
    Material d = bsdf(R"(<bsdf type="diffuse"/>)");
    EXPECT_EQ(d.type, u32(MAT_DIFFUSE));
    EXPECT_FLOAT_EQ(d.kd[1], 0.5f);
    EXPECT_EQ(d.flags & MAT_FLAG_TWO_SIDED, 0u) << "one-sided";
    Material t = bsdf(
        R"(<bsdf type="twosided"><bsdf type="diffuse"><rgb name="reflectance" value="0.2 0.3 0.4"/></bsdf></bsdf>)");
    EXPECT_NE(t.flags & MAT_FLAG_TWO_SIDED, 0u);
    EXPECT_FLOAT_EQ(t.kd[2], 0.4f);
    Material rc = bsdf(R"(<bsdf type="roughconductor"/>)");
    EXPECT_EQ(rc.type, u32(MAT_ROUGH_CONDUCTOR));
    EXPECT_FLOAT_EQ(rc.alpha, 0.1f);
    EXPECT_NE(rc.flags & MAT_FLAG_BECKMANN, 0u) << "Beckmann by default";
    EXPECT_FLOAT_EQ(rc.eta[0], 0) << "material none: a perfect mirror";
    EXPECT_FLOAT_EQ(rc.k[0], 1);
    Material cu = bsdf(R"(<bsdf type="conductor"><string name="material" value="Cu"/></bsdf>)");
    EXPECT_EQ(cu.type, u32(MAT_CONDUCTOR));
    EXPECT_NEAR(cu.eta[0], 0.2004, 1e-3);
    EXPECT_NEAR(cu.k[2], 2.1422, 1e-3);
    Material g = bsdf(
        R"(<bsdf type="roughconductor"><string name="distribution" value="GGX"/><float name="alpha" value="0.3"/><rgb name="eta" value="1 2 3"/><rgb name="k" value="4 5 6"/></bsdf>)");
    EXPECT_EQ(g.flags & MAT_FLAG_BECKMANN, 0u);
    EXPECT_FLOAT_EQ(g.alpha, 0.3f);
    EXPECT_FLOAT_EQ(g.eta[1], 2);
    EXPECT_FLOAT_EQ(g.k[2], 6);
    Material glass = bsdf(R"(<bsdf type="dielectric"/>)");
    EXPECT_EQ(glass.type, u32(MAT_DIELECTRIC));
    EXPECT_FLOAT_EQ(glass.ior, float(1.5046 / 1.000277));
    Material water = bsdf(
        R"(<bsdf type="roughdielectric"><string name="int_ior" value="Water"/><float name="ext_ior" value="1"/><string name="distribution" value="ggx"/></bsdf>)");
    EXPECT_EQ(water.type, u32(MAT_ROUGH_DIELECTRIC));
    EXPECT_FLOAT_EQ(water.ior, 1.333f);
    Material thin = bsdf(
        R"(<bsdf type="thindielectric"><float name="int_ior" value="1.33"/><float name="ext_ior" value="1"/></bsdf>)");
    EXPECT_EQ(thin.type, u32(MAT_THIN_DIELECTRIC));
    EXPECT_FLOAT_EQ(thin.ior, 1.33f);
    Material p = bsdf(R"(<bsdf type="plastic"/>)");
    EXPECT_EQ(p.type, u32(MAT_PLASTIC));
    EXPECT_FLOAT_EQ(p.ior, float(1.49 / 1.000277));
    EXPECT_FLOAT_EQ(p.kd[0], 0.5f);
    Material rp = bsdf(
        R"(<bsdf type="roughplastic"><rgb name="diffuse_reflectance" value="0.1 0.2 0.3"/><float name="alpha" value="0.2"/></bsdf>)");
    EXPECT_EQ(rp.type, u32(MAT_ROUGH_PLASTIC));
    EXPECT_FLOAT_EQ(rp.alpha, 0.2f);
    EXPECT_FLOAT_EQ(rp.kd[2], 0.3f);
    bsdf(R"(<bsdf type="diffuse"><float name="roughness" value="1"/></bsdf>)");
    ASSERT_EQ(w.size(), 2u); // and max_depth's
    EXPECT_NE(w[1].find("'roughness' of bsdf 'diffuse' is not read"), std::string::npos) << w[1];
    EXPECT_EQ(mitsuba_named_ior("Diamond"), 2.419);
    EXPECT_LT(mitsuba_named_ior("unobtainium"), 0);
}

namespace {

// A scene of one rectangle of `bsdf`, with t.png (2 x 1 RGB: (10, 20, 30),
// (200, 100, 50)) beside it.
Scene textured(const std::string& dir_name, const std::string& bsdf) {
    std::string dir = test::scratch_dir("mitsuba-" + dir_name);
    const unsigned char px[6] = {10, 20, 30, 200, 100, 50};
    if (!stbi_write_png((dir + "/t.png").c_str(), 2, 1, 3, px, 6)) throw std::runtime_error("png");
    test::write_file(dir + "/s.xml", scene_xml("<shape type=\"rectangle\">\n" + bsdf + "</shape>"));
    return load_scene(dir + "/s.xml");
}

const Material& last_material(const Scene& s) {
    return s.materials[s.triangles.back().material];
}

std::string textured_error(const std::string& bsdf) {
    return test::message_from(test::input_error_of([&] { textured("texture-errors", bsdf); }),
                              "s.xml:");
}

} // namespace

// bitmap: the image as a colour texture (sRGB) of the material, bilinear,
// or linear data (raw) looked up at the nearest texel; the material's
// constant is the texture's mean linear colour. checkerboard: a 2 x 2
// texture of its two colours, 8-bit linear, looked up at the nearest texel,
// color0 in the top left and bottom right (Mitsuba's v is 1 - v here).
// Every texture error names its line.
TEST(MitsubaTextures, BitmapAndCheckerboardBecomeTheMaterialsTextures) {
    Scene s = textured("bitmap", R"(<bsdf type="diffuse"><texture type="bitmap" name="reflectance">
        <string name="filename" value="t.png"/></texture></bsdf>)");
    const Material& d = last_material(s);
    ASSERT_NE(d.kd_tex, TEX_NONE);
    const SceneTexture& t = s.textures[d.kd_tex];
    EXPECT_EQ(t.kind, TextureKind::Colour);
    EXPECT_FALSE(t.nearest);
    ASSERT_EQ(t.texels.size(), 2u);
    EXPECT_EQ(t.texels[1], 200u | 100u << 8 | 50u << 16 | 255u << 24);
    EXPECT_NEAR(d.kd[0], (srgb_to_linear(10 / 255.0) + srgb_to_linear(200 / 255.0)) / 2, 1e-6);

    Scene r =
        textured("bitmap-raw",
                 R"(<bsdf type="roughplastic"><texture type="bitmap" name="diffuse_reflectance">
        <string name="filename" value="t.png"/><boolean name="raw" value="true"/>
        <string name="filter_type" value="nearest"/></texture></bsdf>)");
    const Material& rp = last_material(r);
    EXPECT_EQ(r.textures[rp.kd_tex].kind, TextureKind::Data);
    EXPECT_TRUE(r.textures[rp.kd_tex].nearest);
    EXPECT_NEAR(rp.kd[1], (20 + 100) / 510.0, 1e-6) << "raw: linear";

    Scene c = textured(
        "checker", R"(<bsdf type="plastic"><texture type="checkerboard" name="diffuse_reflectance">
        <rgb name="color0" value="0.8 0.4 0.2"/></texture></bsdf>)");
    const Material& p = last_material(c);
    const SceneTexture& ct = c.textures[p.kd_tex];
    EXPECT_TRUE(ct.nearest);
    EXPECT_EQ(ct.kind, TextureKind::Data);
    const std::uint32_t c0 = 204u | 102u << 8 | 51u << 16 | 255u << 24,
                        c1 = 51u | 51u << 8 | 51u << 16 | 255u << 24; // color1's default 0.2
    EXPECT_EQ(ct.texels, (std::vector<std::uint32_t>{c0, c1, c1, c0}));
    EXPECT_NEAR(p.kd[0], 0.5, 1e-6);

    Scene k = textured(
        "conductor",
        R"(<bsdf type="conductor"><texture type="checkerboard" name="specular_reflectance"/></bsdf>)");
    EXPECT_NE(last_material(k).ks_tex, TEX_NONE);
    Scene w = textured("wrap", R"(<bsdf type="diffuse"><texture type="bitmap" name="reflectance">
        <string name="filename" value="t.png"/><string name="wrap_mode" value="clamp"/></texture></bsdf>)");
    bool warned = false;
    for (const std::string& m : w.warnings)
        warned |= m.find("s.xml:15: warning: wrap_mode 'clamp'") != std::string::npos;
    EXPECT_TRUE(warned);

    struct Row {
        const char* bsdf;
        const char* want;
    } rows[] = {
        {R"(<bsdf type="diffuse"><texture type="checkerboard" name="reflectance">
            <transform name="to_uv"><scale value="4"/></transform></texture></bsdf>)",
         "s.xml:15: 'to_uv' other than the identity is not read"},
        {R"(<bsdf type="roughconductor">
            <texture type="checkerboard" name="alpha"/></bsdf>)",
         "s.xml:15: texture 'checkerboard' as 'alpha' is not read"},
        {R"(<bsdf type="diffuse">
            <texture type="perlin" name="reflectance"/></bsdf>)",
         "s.xml:15: texture 'perlin': is not read (bitmap and checkerboard are)"},
        {R"(<bsdf type="diffuse">
            <texture type="bitmap" name="reflectance"/></bsdf>)",
         "s.xml:15: texture 'bitmap': needs a 'filename'"},
        {R"(<bsdf type="diffuse"><texture type="checkerboard" name="reflectance">
            <rgb name="color1" value="2"/></texture></bsdf>)",
         "texture 'checkerboard': colours must lie in [0, 1]"},
    };
    for (const Row& row : rows) {
        std::string got = textured_error(row.bsdf);
        EXPECT_NE(got.find(row.want), std::string::npos)
            << "got: " << got << "\nwant: " << row.want;
    }
}

TEST(MitsubaScene, SensorFilmAndIntegrator) {
    Scene s = load(
        "sensor",
        scene_xml(R"(<integrator type="path"><integer name="max_depth" value="5"/></integrator>)"));
    EXPECT_EQ(s.width, 32);
    EXPECT_EQ(s.height, 24);
    EXPECT_EQ(s.depth, 4) << "max_depth 5: four bounces";
    expect_vec(s.camera.eye, {0, 1, 3.4f}, 1e-6, "eye");
    expect_vec(normalize(s.camera.target - s.camera.eye), {0, 0, -1}, 1e-6, "view");
    expect_vec(s.camera.up, {0, 1, 0}, 1e-6, "up");
    EXPECT_NEAR(s.camera.fov_y_deg, 40, 1e-4) << "fov_axis y";
    // fov_axis x, diagonal, smaller and larger on the 32 x 24 film.
    const double t = std::tan(40 * M_PI / 360), aspect = 32.0 / 24;
    struct {
        const char* axis;
        double tan_y;
    } axes[] = {{"x", t / aspect},
                {"diagonal", t / std::sqrt(1 + aspect * aspect)},
                {"smaller", t},
                {"larger", t / aspect}};
    for (const auto& a : axes) {
        std::string xml = scene_xml("");
        xml.replace(xml.find("value=\"y\""), 9, std::string("value=\"") + a.axis + "\"");
        Scene f = load("fov", xml);
        EXPECT_NEAR(std::tan(f.camera.fov_y_deg * M_PI / 360), a.tan_y, 1e-6) << a.axis;
    }
    Scene unlimited = load("depth", scene_xml(""));
    EXPECT_EQ(unlimited.depth, kMaxDepth);
    bool warned = false;
    for (const std::string& w : unlimited.warnings)
        warned = warned || w.find("max_depth -1 (no limit) is read as 64") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(MitsubaXml, DefaultsIncludesAndRefs) {
    const char* inc =
        R"(<scene version="3.0.0"><bsdf type="diffuse" id="grey"><rgb name="reflectance" value="$grey"/></bsdf></scene>)";
    Scene s = load("refs", scene_xml(R"(<default name="grey" value="0.25"/>
        <include filename="inc.xml"/>
        <shape type="rectangle"><ref id="grey"/></shape>
        <shape type="cube"><ref name="bsdf" id="grey"/></shape>)"),
                   {{"inc.xml", inc}});
    const Material& m = s.materials[s.triangles.back().material];
    EXPECT_FLOAT_EQ(m.kd[0], 0.25f);
    EXPECT_EQ(s.triangles[2].material, s.triangles.back().material) << "one BSDF, one material";
}

TEST(MitsubaXml, OldAndNewSyntaxGiveTheSameScene) {
    const char* v3 = R"(<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value="4"/></integrator>
    <sensor type="perspective"><float name="fov" value="35"/><string name="fov_axis" value="x"/>
        <transform name="to_world"><lookat origin="0,1,4" target="0,1,0" up="0,1,0"/></transform>
        <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="12"/><rfilter type="box"/></film></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="0.2"/><rotate x="1" angle="90"/><translate y="2"/></transform>
        <emitter type="area"><rgb name="radiance" value="5 4 3"/></emitter></shape>
    <shape type="cube"><bsdf type="dielectric"><float name="int_ior" value="1.33"/></bsdf></shape>
    <shape type="sphere"><bsdf type="roughplastic"><rgb name="diffuse_reflectance" value="0.5 0.2 0.1"/><float name="int_ior" value="1.5"/></bsdf></shape>
</scene>)";
    const char* v06 = R"(<scene version="0.6.0">
    <integrator type="path"><integer name="maxDepth" value="4"/></integrator>
    <sensor type="perspective"><float name="fov" value="35"/><string name="fovAxis" value="x"/>
        <transform name="toWorld"><lookAt origin="0,1,4" target="0,1,0" up="0,1,0"/></transform>
        <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="12"/><rfilter type="box"/></film></sensor>
    <shape type="rectangle"><transform name="toWorld"><scale value="0.2"/><rotate x="1" angle="90"/><translate y="2"/></transform>
        <emitter type="area"><rgb name="radiance" value="5 4 3"/></emitter></shape>
    <shape type="cube"><bsdf type="dielectric"><float name="intIOR" value="1.33"/></bsdf></shape>
    <shape type="sphere"><bsdf type="roughplastic"><rgb name="diffuseReflectance" value="0.5 0.2 0.1"/><float name="intIOR" value="1.5"/></bsdf></shape>
</scene>)";
    Scene a = load("v3", v3), b = load("v06", v06);
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    for (std::size_t i = 0; i < a.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k)
            expect_vec(a.triangles[i].v[k], b.triangles[i].v[k], 0, "vertex");
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i)
        EXPECT_EQ(std::memcmp(&a.materials[i], &b.materials[i], sizeof(Material)), 0) << i;
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.camera.fov_y_deg, b.camera.fov_y_deg);
    // The same warnings at the same lines (the files differ in their names).
    ASSERT_EQ(a.warnings.size(), b.warnings.size());
    for (std::size_t i = 0; i < a.warnings.size(); ++i)
        EXPECT_EQ(a.warnings[i].substr(a.warnings[i].find(".xml:")),
                  b.warnings[i].substr(b.warnings[i].find(".xml:")));
}

TEST(MitsubaXml, EveryErrorNamesItsFileAndLine) {
    struct Row {
        std::string xml;
        const char* want;
    } rows[] = {
        {"<scene>\n</scene>", "s.xml:1: <scene> needs version=\"X.Y.Z\""},
        {"<scene version=\"3.0.0\">\n<shape type=\"rectangle\">\n</scene>",
         "s.xml:3: not well-formed XML"},
        {"<scene version=\"3.0.0\">\n<shape type=\"torus\"/>\n" + std::string(kSensor) + "</scene>",
         "s.xml:2: shape 'torus' is not read"},
        {scene_xml("<shape type=\"rectangle\">\n<bsdf type=\"velvet\"/></shape>"),
         "bsdf 'velvet': is not read (diffuse, twosided"},
        {scene_xml("<shape type=\"rectangle\"><bsdf type=\"diffuse\">\n<rgb name=\"reflectance\" "
                   "value=\"$nope\"/></bsdf></shape>"),
         "parameter '$nope' has no value"},
        {scene_xml("<shape type=\"rectangle\">\n<ref id=\"missing\"/></shape>"),
         "<ref id=\"missing\"> names no object"},
        {scene_xml("\n<emitter type=\"envmap\"/>"), "emitter 'envmap' is not read"},
        {scene_xml("<shape type=\"rectangle\"><bsdf type=\"diffuse\">\n<spectrum "
                   "name=\"reflectance\" value=\"400:0.1, 700:0.5\"/></bsdf></shape>"),
         "a spectrum of wavelength:value pairs is not read"},
        {scene_xml("\n<include filename=\"gone.xml\"/>"), "cannot open included file"},
        {scene_xml("<shape type=\"rectangle\"><bsdf type=\"conductor\">\n<string name=\"material\" "
                   "value=\"Unobtainium\"/></bsdf></shape>"),
         "material 'Unobtainium' is not in Mitsuba's table of conductors"},
        {scene_xml("<shape type=\"rectangle\"><bsdf type=\"diffuse\">\n<float name=\"reflectance\" "
                   "value=\"x\"/></bsdf></shape>"),
         "is not a number"},
        {scene_xml("<shape type=\"rectangle\"><transform name=\"to_world\">\n<rotate "
                   "angle=\"3\"/></transform></shape>"),
         "rotate: the axis is zero"},
        {scene_xml("<shape type=\"rectangle\"><transform name=\"to_world\">\n<matrix value=\"1 2 "
                   "3\"/></transform></shape>"),
         "matrix takes 9 or 16 numbers"},
        {scene_xml("<shape type=\"rectangle\"><transform name=\"to_world\">\n<lookat origin=\"0 0 "
                   "0\" target=\"0 0 1\"/></transform></shape>"),
         "lookat without 'up'"},
        {scene_xml("<shape type=\"rectangle\"><bsdf type=\"diffuse\" id=\"a\"/></shape>\n<bsdf "
                   "type=\"diffuse\" id=\"a\"/>"),
         "id 'a' is used twice"},
        {scene_xml(
             "<shape type=\"rectangle\">\n<float name=\"flip_normals\" value=\"1\"/></shape>"),
         "'flip_normals' is <float>; it must be a <boolean>"},
    };
    for (const Row& r : rows) {
        std::string got = load_error("errors", r.xml);
        EXPECT_NE(got.find(r.want), std::string::npos) << "got: " << got << "\nwant: " << r.want;
        // Every message but the include's names a line of s.xml.
        EXPECT_EQ(got.rfind("s.xml:", 0), 0u) << got;
    }
}

namespace {

const char* const kProjectScenes[] = {
    "ajar",          "blender-export",       "cornell", "cornell-glass", "cornell-glossy",
    "cornell-water", "cornell-water-smooth", "furnace", "tiny-caustic",  "veach-mis",
    "water-spark"};

} // namespace

// Each scene's .xml (scenes/generate.py) is its .scene: the same film, camera,
// depth and triangles in the same order, each of the same material, and the
// same textures, bit for bit.
TEST(MitsubaScenes, EveryProjectSceneReadsTheSameFromItsXml) {
    for (const char* name : kProjectScenes) {
        SCOPED_TRACE(name);
        Scene a = load_scene(std::string("scenes/") + name + ".scene");
        Scene b = load_scene(std::string("scenes/") + name + ".xml");
        EXPECT_EQ(a.width, b.width);
        EXPECT_EQ(a.height, b.height);
        EXPECT_EQ(a.depth, b.depth);
        EXPECT_EQ(std::memcmp(&a.camera, &b.camera, sizeof(Camera)), 0);
        ASSERT_EQ(a.triangles.size(), b.triangles.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < a.triangles.size(); ++i) {
            const SceneTriangle &s = a.triangles[i], &x = b.triangles[i];
            bool same = std::memcmp(s.v, x.v, sizeof(s.v)) == 0 &&
                        std::memcmp(s.n, x.n, sizeof(s.n)) == 0 &&
                        std::memcmp(s.uv, x.uv, sizeof(s.uv)) == 0 && s.smooth == x.smooth &&
                        std::memcmp(&a.materials[s.material], &b.materials[x.material],
                                    sizeof(Material)) == 0;
            differ += !same;
        }
        EXPECT_EQ(differ, 0u) << "triangles that differ";
        ASSERT_EQ(a.textures.size(), b.textures.size());
        for (std::size_t i = 0; i < a.textures.size(); ++i) {
            const SceneTexture &s = a.textures[i], &x = b.textures[i];
            EXPECT_TRUE(s.kind == x.kind && s.width == x.width && s.height == x.height &&
                        s.texels == x.texels && s.nearest == x.nearest)
                << "texture " << i << " (" << s.file << ", " << x.file << ")";
        }
        EXPECT_TRUE(b.warnings.empty()) << b.warnings.front();
    }
}

// And so they render the same image, bit for bit, for a seed: path tracing
// and MLT.
TEST(MitsubaScenes, XmlAndSceneRenderTheSameImage) {
    for (const char* name : {"cornell-glossy", "cornell-water-smooth"}) {
        SCOPED_TRACE(name);
        DeviceScene a = prepare_scene(test::scene(name, 16, 16));
        Scene xml = load_scene(std::string("scenes/") + name + ".xml");
        xml.width = xml.height = 16;
        DeviceScene b = prepare_scene(xml);
        EXPECT_EQ(test::render_pt(a, 7, 4).rgb, test::render_pt(b, 7, 4).rgb) << "PT";
        MltOptions opt = test::plain_mlt();
        opt.threads = 256;
        Image img[2];
        const DeviceScene* ds[2] = {&a, &b};
        for (int k = 0; k < 2; ++k) {
            MltRenderer m(test::cl(), *ds[k], opt);
            m.prepare();
            m.step(8);
            img[k] = m.image();
        }
        EXPECT_EQ(img[0].rgb, img[1].rgb) << "MLT";
    }
}
