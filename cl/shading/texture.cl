/* Textures: 8-bit RGBA texels (TextureInfo, cl/core/shared_types.h), looked
 * up bilinearly (or at the nearest texel) with wrap at (u, v), v = 1 the
 * top row; colour textures are
 * decoded from sRGB per texel, before filtering. A material's textures
 * replace its constants at the hit (tex_apply); a cut-out texture makes
 * holes where its alpha is below 1/2 (tex_is_hole). */

inline float tex_srgb_to_linear(float c) {
    return c <= 0.04045f ? c * (1.0f / 12.92f) : pow((c + 0.055f) * (1.0f / 1.055f), 2.4f);
}

inline float4 tex_texel(const __global TextureInfo* t, const __global Texel* texels, int x, int y) {
    uint w = t->width, h = t->height;
    uint xi = (uint)(x % (int)w + (int)w) % w, yi = (uint)(y % (int)h + (int)h) % h;
    uint v = texels[t->first + yi * w + xi];
    float4 c = (float4)((float)(v & 0xFFu), (float)((v >> 8) & 0xFFu), (float)((v >> 16) & 0xFFu),
                        (float)(v >> 24)) *
               (1.0f / 255.0f);
    if ((t->flags & TEX_FLAG_SRGB) != 0u) {
        c.x = tex_srgb_to_linear(c.x);
        c.y = tex_srgb_to_linear(c.y);
        c.z = tex_srgb_to_linear(c.z);
    }
    return c;
}

/* RGBA of texture `index` at uv, wrapping: bilinear between texel centres,
 * or the texel uv falls in (TEX_FLAG_NEAREST). */
inline float4 tex_lookup(const __global TextureInfo* infos, const __global Texel* texels,
                         uint index, float2 uv) {
    const __global TextureInfo* t = &infos[index];
    if ((t->flags & TEX_FLAG_NEAREST) != 0u)
        return tex_texel(t, texels, (int)floor(uv.x * (float)t->width),
                         (int)floor((1.0f - uv.y) * (float)t->height));
    float fx = uv.x * (float)t->width - 0.5f, fy = (1.0f - uv.y) * (float)t->height - 0.5f;
    float x0 = floor(fx), y0 = floor(fy);
    float ax = fx - x0, ay = fy - y0;
    int x = (int)x0, y = (int)y0;
    float4 c00 = tex_texel(t, texels, x, y), c10 = tex_texel(t, texels, x + 1, y);
    float4 c01 = tex_texel(t, texels, x, y + 1), c11 = tex_texel(t, texels, x + 1, y + 1);
    return mix(mix(c00, c10, ax), mix(c01, c11, ax), ay);
}

inline bool tex_is_hole(const Material* m, const __global TextureInfo* infos,
                        const __global Texel* texels, float2 uv) {
    return m->alpha_tex != TEX_NONE && tex_lookup(infos, texels, m->alpha_tex, uv).w < 0.5f;
}

/* The material at the hit: its textured parameters looked up at uv. */
inline void tex_apply(Material* m, const __global TextureInfo* infos, const __global Texel* texels,
                      float2 uv) {
    if (m->kd_tex != TEX_NONE) {
        float4 c = tex_lookup(infos, texels, m->kd_tex, uv);
        m->kd[0] = c.x;
        m->kd[1] = c.y;
        m->kd[2] = c.z;
    }
    if (m->ks_tex != TEX_NONE) {
        float4 c = tex_lookup(infos, texels, m->ks_tex, uv);
        m->ks[0] = c.x;
        m->ks[1] = c.y;
        m->ks[2] = c.z;
    }
    if (m->rough_tex != TEX_NONE) {
        float r = tex_lookup(infos, texels, m->rough_tex, uv).x;
        m->alpha = fmax(r * r, MAT_MIN_ROUGH_ALPHA);
    }
}
