#include "scene/device_scene.hpp"

#include "base/color.hpp"

#include <cmath>

namespace smallmlt {

namespace {

double luminance(const f32 c[3]) {
    return rgb_luminance(c[0], c[1], c[2]);
}

// Light table: emitters picked in proportion to power (area x luminance of
// Ke) through an integer CDF over 2^bits grid points, each light getting at
// least one, so pick probabilities are exact at the slot's precision.
void build_lights(DeviceScene& ds) {
    std::vector<std::uint32_t> emitters;
    for (std::uint32_t i = 0; i < ds.tris.size(); ++i)
        if (ds.materials[ds.tris[i].material].emissive) emitters.push_back(i);
    std::uint32_t n = static_cast<std::uint32_t>(emitters.size());
    if (n == 0) return;
    int bits = light_pick_bits(n);
    std::uint64_t grid = std::uint64_t(1) << bits;
    std::vector<double> power(n);
    double sum = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        const Triangle& t = ds.tris[emitters[k]];
        Vec3 e1{t.e1[0], t.e1[1], t.e1[2]}, e2{t.e2[0], t.e2[1], t.e2[2]};
        power[k] = 0.5 * length(cross(e1, e2)) * luminance(ds.materials[t.material].ke);
        sum += power[k];
    }
    std::uint64_t spare = grid - n, used = 0;
    std::vector<std::uint64_t> units(n);
    for (std::uint32_t k = 0; k < n; ++k) {
        units[k] = 1 + static_cast<std::uint64_t>(std::floor(power[k] / sum * double(spare)));
        used += units[k];
    }
    units[n - 1] += grid - used; // rounding remainder
    std::uint64_t cdf = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        cdf += units[k];
        Triangle& t = ds.tris[emitters[k]];
        t.light_pick_prob = static_cast<float>(double(units[k]) / double(grid));
        t.light_index = k;
        ds.lights.push_back({emitters[k], static_cast<std::uint32_t>(cdf)});
    }
}

} // namespace

Frame make_frame(const Camera& cam, int width, int height, int depth) {
    Vec3 forward = normalize(cam.target - cam.eye);
    Vec3 right = normalize(cross(forward, cam.up));
    Vec3 up = cross(right, forward);
    float half_h = std::tan(cam.fov_y_deg * 0.5f * 3.14159265358979f / 180.0f);
    float half_w = half_h * float(width) / float(height);
    Frame f{};
    store3(f.eye, cam.eye);
    store3(f.top_left, forward - right * half_w + up * half_h);
    store3(f.du, right * (2.0f * half_w));
    store3(f.dv, up * (-2.0f * half_h));
    f.width = static_cast<u32>(width);
    f.height = static_cast<u32>(height);
    f.depth = static_cast<u32>(depth);
    return f;
}

DeviceScene prepare_scene(const Scene& scene) {
    DeviceScene ds;
    Bvh bvh = bvh_build(scene.triangles);
    ds.nodes = std::move(bvh.nodes);
    ds.materials = scene.materials;
    SceneFeatures features;
    features.depth = scene.depth;
    for (const SceneTriangle& st : scene.triangles)
        features.shading_normals |= st.smooth;
    for (const Material& m : scene.materials) {
        features.textures |= m.kd_tex != TEX_NONE || m.ks_tex != TEX_NONE ||
                             m.rough_tex != TEX_NONE || m.alpha_tex != TEX_NONE;
        features.cutouts |= m.alpha_tex != TEX_NONE;
    }
    for (std::uint32_t src : bvh.order) {
        const SceneTriangle& st = scene.triangles[src];
        Triangle t{};
        store3(t.v0, st.v[0]);
        store3(t.e1, st.v[1] - st.v[0]);
        store3(t.e2, st.v[2] - st.v[0]);
        t.material = st.material;
        t.light_index = LIGHT_NONE;
        ds.tris.push_back(t);
        if (features.shading_normals) {
            Vec3 ng = normalize(cross(st.v[1] - st.v[0], st.v[2] - st.v[0]));
            TriangleNormals tn{};
            store3(tn.n0, st.smooth ? st.n[0] : ng);
            store3(tn.n1, st.smooth ? st.n[1] : ng);
            store3(tn.n2, st.smooth ? st.n[2] : ng);
            ds.normals.push_back(tn);
        }
        if (features.textures) {
            TriangleUVs uv{};
            for (int c = 0; c < 2; ++c) {
                uv.uv0[c] = st.uv[0][c];
                uv.uv1[c] = st.uv[1][c];
                uv.uv2[c] = st.uv[2][c];
            }
            ds.uvs.push_back(uv);
        }
        const Material& m = scene.materials[st.material];
        features.with(m.type);
    }
    for (const SceneTexture& t : scene.textures) {
        TextureInfo info{};
        info.first = static_cast<u32>(ds.texels.size());
        info.width = static_cast<u32>(t.width);
        info.height = static_cast<u32>(t.height);
        info.flags = (t.kind == TextureKind::Colour ? TEX_FLAG_SRGB : 0u) |
                     (t.nearest ? TEX_FLAG_NEAREST : 0u);
        ds.textures.push_back(info);
        ds.texture_files.push_back(t.file);
        ds.texels.insert(ds.texels.end(), t.texels.begin(), t.texels.end());
    }
    // Buffers a scene does not use are bound with one entry, never read.
    if (ds.normals.empty()) ds.normals.push_back(TriangleNormals{});
    if (ds.uvs.empty()) ds.uvs.push_back(TriangleUVs{});
    if (ds.textures.empty()) ds.textures.push_back(TextureInfo{});
    if (ds.texels.empty()) ds.texels.push_back(0);
    build_lights(ds);
    features.num_lights = static_cast<std::uint32_t>(ds.lights.size());
    ds.layout = make_layout(features, scene.roulette);
    ds.frame = make_frame(scene.camera, scene.width, scene.height, scene.depth);
    ds.frame.num_lights = features.num_lights;
    return ds;
}

} // namespace smallmlt
