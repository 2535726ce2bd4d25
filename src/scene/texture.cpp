#include "scene/texture.hpp"

#include "base/error.hpp"

#include <stb/stb_image.h>

#include <algorithm>
#include <cmath>

namespace smallmlt {

double srgb_to_linear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linear_to_srgb(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
}

namespace {

Vec3 texel_colour(const SceneTexture& t, std::uint32_t v) {
    double c[3];
    for (int k = 0; k < 3; ++k) {
        double u = double((v >> (8 * k)) & 0xFFu) / 255.0;
        c[k] = t.kind == TextureKind::Colour ? srgb_to_linear(u) : u;
    }
    return {float(c[0]), float(c[1]), float(c[2])};
}

} // namespace

Vec3 texture_mean(const SceneTexture& t) {
    double s[3] = {0, 0, 0};
    for (std::uint32_t v : t.texels) {
        Vec3 c = texel_colour(t, v);
        s[0] += c.x, s[1] += c.y, s[2] += c.z;
    }
    double n = double(std::max<std::size_t>(1, t.texels.size()));
    return {float(s[0] / n), float(s[1] / n), float(s[2] / n)};
}

SceneTexture load_texture(const std::string& path, TextureKind kind, const std::string& where) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* px = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!px)
        throw InputError(where + ": cannot read texture " + path + ": " + stbi_failure_reason());
    SceneTexture t;
    t.file = path;
    t.kind = kind;
    t.width = w;
    t.height = h;
    t.texels.resize(std::size_t(w) * h);
    const bool alpha_from_red = kind == TextureKind::Mask && (channels == 1 || channels == 3);
    for (std::size_t i = 0; i < t.texels.size(); ++i) {
        const stbi_uc* p = px + 4 * i;
        std::uint32_t a = alpha_from_red ? p[0] : p[3];
        t.texels[i] =
            std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | a << 24;
    }
    stbi_image_free(px);
    return t;
}

void halve(SceneTexture& t) {
    const int w = std::max(1, t.width / 2), h = std::max(1, t.height / 2);
    const bool srgb = t.kind == TextureKind::Colour;
    std::vector<std::uint32_t> out(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum[4] = {0, 0, 0, 0};
            int n = 0;
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    int sx = std::min(t.width - 1, 2 * x + dx),
                        sy = std::min(t.height - 1, 2 * y + dy);
                    std::uint32_t v = t.texels[std::size_t(sy) * t.width + sx];
                    for (int c = 0; c < 4; ++c) {
                        double u = double((v >> (8 * c)) & 0xFFu) / 255.0;
                        sum[c] += (srgb && c < 3) ? srgb_to_linear(u) : u;
                    }
                    ++n;
                }
            std::uint32_t v = 0;
            for (int c = 0; c < 4; ++c) {
                double m = sum[c] / n;
                if (srgb && c < 3) m = linear_to_srgb(m);
                v |= std::uint32_t(std::lround(std::clamp(m, 0.0, 1.0) * 255.0)) << (8 * c);
            }
            out[std::size_t(y) * w + x] = v;
        }
    t.width = w;
    t.height = h;
    t.texels = std::move(out);
    ++t.halvings;
}

int fit_textures(std::vector<SceneTexture>& textures, std::uint64_t max_bytes, int max_side) {
    int done = 0;
    auto total = [&] {
        std::uint64_t b = 0;
        for (const SceneTexture& t : textures)
            b += t.bytes();
        return b;
    };
    for (SceneTexture& t : textures)
        while (max_side > 0 && std::max(t.width, t.height) > max_side) {
            halve(t);
            ++done;
        }
    while (total() > max_bytes) {
        auto big = std::max_element(
            textures.begin(), textures.end(),
            [](const SceneTexture& a, const SceneTexture& b) { return a.bytes() < b.bytes(); });
        if (big == textures.end() || big->texels.size() <= 1) break;
        halve(*big);
        ++done;
    }
    return done;
}

} // namespace smallmlt
