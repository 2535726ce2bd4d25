/* Structs seen by both the host (C++17) and the kernels (OpenCL C 1.2).
 * This header is their only definition. Fields are 32-bit scalars or arrays
 * of them, so size and offsets are the same on every compiler; the host
 * static_asserts them (src/scene/shared_layout.cpp) and a probe kernel
 * reports the device's view for a test to compare. */
#ifndef SMALLMLT_SHARED_TYPES_H
#define SMALLMLT_SHARED_TYPES_H

#ifdef __OPENCL_VERSION__
typedef uint u32;
typedef ulong u64;
typedef float f32;
#else
#include <cstdint>
typedef std::uint32_t u32;
typedef std::uint64_t u64;
typedef float f32;
#endif

/* The scattering models (cl/shading/<model>.cl), one list:
 * X(NAME, Material.type, the numbers a bounce at it reads). MAT_USES_PAIR:
 * the BSDF pair (a direction); MAT_USES_CHOICE: the 16-bit lobe choice;
 * MAT_USES_NEE: it has a lobe that is not a Dirac delta, so next-event
 * estimation runs at it (and reads the light numbers). The host derives the
 * scene's sample layout from it (src/scene/sample_layout.cpp) and the
 * kernels read by it (cl/shading/shading.cl). */
#define MAT_USES_PAIR 1u
#define MAT_USES_CHOICE 2u
#define MAT_USES_NEE 4u
#define MAT_MODELS(X)                                                                              \
    X(DIFFUSE, 0, MAT_USES_PAIR | MAT_USES_NEE)                                                    \
    X(CONDUCTOR, 1, 0u)                                                                            \
    X(DIELECTRIC, 2, MAT_USES_CHOICE)                                                              \
    X(ROUGH_CONDUCTOR, 3, MAT_USES_PAIR | MAT_USES_NEE)                                            \
    X(ROUGH_DIELECTRIC, 4, MAT_USES_PAIR | MAT_USES_CHOICE | MAT_USES_NEE)                         \
    X(PLASTIC, 5, MAT_USES_PAIR | MAT_USES_CHOICE | MAT_USES_NEE)                                  \
    X(ROUGH_PLASTIC, 6, MAT_USES_PAIR | MAT_USES_CHOICE | MAT_USES_NEE)                            \
    X(THIN_DIELECTRIC, 7, MAT_USES_CHOICE)

#define MAT_TYPE_ID(NAME, id, uses) MAT_##NAME = id,
enum { MAT_MODELS(MAT_TYPE_ID) MAT_TYPES };
#undef MAT_TYPE_ID

/* The least alpha of a rough model (below it a material is smooth; a rough
 * texel is clamped to it). */
#define MAT_MIN_ROUGH_ALPHA 1e-3f

/* Material.flags: MAT_FLAG_BECKMANN, the microfacet distribution is
 * Beckmann's (else GGX); MAT_FLAG_TWO_SIDED, an opaque model reflects on both
 * sides (else its back is black). */
#define MAT_FLAG_BECKMANN 1u
#define MAT_FLAG_TWO_SIDED 2u

/* Material.coat_t: COAT_T_SIZE 16-bit entries, two to a word. */
#define COAT_T_SIZE 32
#define COAT_T_ONE 65535.0f
#define COAT_T_WORD(i) ((i) >> 1)
#define COAT_T_SHIFT(i) (((i)&1) * 16)

/* Marks "no light" in Triangle.light_index. */
#define LIGHT_NONE 0xFFFFFFFFu

/* One triangle: v0 and the edges e1 = v1 - v0, e2 = v2 - v0 (world units).
 * The geometric normal cross(e1, e2) is its front face (counter-clockwise).
 * light_pick_prob is the probability that next-event estimation picks this
 * triangle (0 if it does not emit). 48 bytes. */
typedef struct {
    f32 v0[3];
    u32 material;
    f32 e1[3];
    f32 light_pick_prob;
    f32 e2[3];
    u32 light_index;
} Triangle;

/* The shading normals of a triangle (unit, world space) at v0, v1, v2, for
 * scenes with vertex normals (SceneFeatures.shading_normals); a
 * one-element buffer otherwise. 36 bytes. */
typedef struct {
    f32 n0[3];
    f32 n1[3];
    f32 n2[3];
} TriangleNormals;

/* Flattened BVH node, depth-first order. count == 0: interior node whose
 * first child is the next node and second child is node `offset`.
 * count > 0: leaf holding triangles offset .. offset + count - 1. 32 bytes. */
typedef struct {
    f32 lo[3];
    u32 offset;
    f32 hi[3];
    u32 count;
} BvhNode;

/* A material: `type` is its model (MAT_MODELS), which reads only its own
 * fields. Colours are RGB.
 * - kd: diffuse albedo (diffuse; plastic's base);
 * - ke: emitted radiance (W sr^-1 m^-2 per channel, front face only);
 *   emissive is 1 when any ke channel is > 0; any model may emit;
 * - ks: specular reflectance, a factor on the Fresnel term (conductors,
 *   plastic's coat) or on both lobes (dielectrics);
 * - ior: a dielectric's or a plastic coat's index of refraction relative to
 *   the front side (the inside of a dielectric is behind its triangles);
 * - eta, k: a conductor's complex index of refraction eta + i k, relative to
 *   the front side; eta 0, k 1 reflects everything (Fresnel term 1);
 * - alpha: microfacet roughness (GGX or Beckmann alpha, rough models);
 * - flags: MAT_FLAG_*;
 * - fdr_int: plastic: the coat's hemispherical reflectance from inside
 *   (the host integrates it: src/scene/material.cpp for a smooth coat,
 *   src/scene/plastic_coat.cpp for a rough one);
 * - spec_weight: plastic: the share of its lobe choice given to the coat
 *   before Fresnel, lum(ks) / (lum(ks) + lum(kd)) of the constant colours
 *   (a texture does not change it: it steers sampling only);
 * - kd_tex, ks_tex, rough_tex, alpha_tex: textures (TextureInfo index, or
 *   TEX_NONE) that replace kd, ks, the roughness (alpha = texel^2) and
 *   give the cut-out (a texel below 1/2 is a hole), at the hit's (u, v);
 * - coat_t: rough plastic: the coat's transmittance t(cos) at
 *   cos = i / (COAT_T_SIZE - 1), entry i in bits COAT_T_SHIFT(i) of word
 *   COAT_T_WORD(i), t = bits / COAT_T_ONE (linear between entries).
 * 168 bytes. */
typedef struct {
    f32 kd[3];
    u32 type;
    f32 ke[3];
    f32 ior;
    f32 ks[3];
    u32 emissive;
    f32 eta[3];
    f32 alpha;
    f32 k[3];
    u32 flags;
    f32 fdr_int;
    f32 spec_weight;
    u32 kd_tex;
    u32 ks_tex;
    u32 rough_tex;
    u32 alpha_tex;
    u32 coat_t[COAT_T_SIZE / 2];
} Material;

#define TEX_NONE 0xFFFFFFFFu

/* A texture in the texel buffer: width x height texels from texel `first`,
 * row-major from the top row (v = 1), each 8-bit RGBA with R in the low
 * byte; flags: TEX_FLAG_SRGB, colour values, sRGB-encoded and decoded at
 * lookup (else linear data); TEX_FLAG_NEAREST, looked up at the texel the
 * point falls in (else bilinearly). 16 bytes. */
typedef struct {
    u32 first;
    u32 width;
    u32 height;
    u32 flags;
} TextureInfo;

#define TEX_FLAG_SRGB 1u
#define TEX_FLAG_NEAREST 2u

typedef u32 Texel;

/* The texture coordinates of a triangle at v0, v1, v2, for scenes with
 * textures (a one-element buffer otherwise). 24 bytes. */
typedef struct {
    f32 uv0[2];
    f32 uv1[2];
    f32 uv2[2];
} TriangleUVs;

/* An emissive triangle for next-event estimation. The triangle is picked when
 * the light-pick number u (an integer in [0, 2^bits)) satisfies
 * cdf_lo <= u < cdf_hi, so the pick probability is exactly
 * (cdf_hi - cdf_lo) / 2^bits at the slot's stored precision. 8 bytes. */
typedef struct {
    u32 triangle;
    u32 cdf_hi;
} LightEntry;

/* Pinhole camera and film. A film position (fx, fy) in [0,1)^2 maps to the
 * direction top_left + fx * du + fy * dv (fy = 0 is the top row). 64 bytes. */
typedef struct {
    f32 eye[3];
    u32 width;
    f32 top_left[3];
    u32 height;
    f32 du[3];
    u32 depth;
    f32 dv[3];
    u32 num_lights;
} Frame;

/* A chain's value beside its packed numbers: G(x) = F(x) w(x), the RGB
 * contribution of the path of its current state x times the target's weight
 * at its pixel (cl/mlt/mlt_step.cl; lum(G) is the target I), and in `meta`:
 * - bits 0-7: how many bounces of x's numbers are live (the path scattered
 *   that many times; numbers of later bounces are dead and drawn afresh when
 *   a proposal reaches them);
 * - bit 8: the chain has been stuck (a run of stuck_run rejections);
 * - bits 9-31: its current run of consecutive rejections (saturating);
 * and in `stay` the stay weight x has gathered and not yet splatted, in
 * fixed point with MLT_STAY_FRAC_BITS fraction bits: a chain splats x once,
 * when it moves away (or when the weight reaches MLT_STAY_FLUSH), not at
 * every step it stays. 20 bytes. */
typedef struct {
    f32 rgb[3];
    u32 meta;
    u32 stay;
} ChainValue;

#define MLT_STAY_FRAC_BITS 24
/* A pending weight at or above this (128) is splatted at once, so that adding
 * a step's weight (at most K <= 64) never overflows 32 bits. */
#define MLT_STAY_FLUSH 0x80000000u

/* Modes of the kernel mlt_owed (cl/kernels/mlt.cl), which splats what each
 * chain owes the film: ADD adds it and UNDO subtracts it again, exactly, so
 * that the host's read between the two changes nothing; FLUSH adds it and
 * clears the chain's weight, so that a pass ends with nothing owed. */
#define MLT_OWED_ADD 0u
#define MLT_OWED_UNDO 1u
#define MLT_OWED_FLUSH 2u

#define CHAIN_BOUNCES_MASK 0xFFu
#define CHAIN_STUCK_BIT 0x100u
#define CHAIN_RUN_SHIFT 9
#define CHAIN_RUN_MAX 0x7FFFFFu

/* The MLT film on the device (cl/mlt/film.cl): pixel p lies in band
 * p / band_pixels at pixel index p % band_pixels, as `layers` layers of
 * three words (R, G, B) of fixed point with frac_bits fraction bits;
 * scale = 2^frac_bits. Layer FILM_LAYER_CHAINS holds the chains' estimate;
 * with Kelemen's weights, layer FILM_LAYER_LARGE holds the large steps' own
 * (src/render/mlt_film.hpp). Words are 32-bit, except in the 64-bit
 * reference build (FILM_ATOMICS64), whose one band has FILM64_FRAC_BITS.
 * 20 bytes. */
typedef struct {
    u32 band_pixels;
    u32 bands;
    u32 frac_bits;
    f32 scale;
    u32 layers;
} FilmShape;

#define FILM_LAYER_CHAINS 0u
#define FILM_LAYER_LARGE 1u

/* The cells of the chains' target weight (cl/mlt/mlt_step.cl, mlt_weight):
 * pixel (x, y) lies in cell (y >> shift) * columns + (x >> shift), of
 * 2^shift x 2^shift pixels; the target is I = lum(F) times its cell's weight
 * (src/render/target.hpp). One cell of weight 1 is the plain luminance.
 * 8 bytes. */
typedef struct {
    u32 shift;
    u32 columns;
} TargetCells;

/* Where the burn-in's samples lie on the film (cl/core/burnin_order.h,
 * cl/sampling/burnin_film.cl): sample g = round * per_round + index, with
 * h = g + offset, lies in pixel ((h mod P) * step) mod P (P pixels, step
 * coprime with P), in the Sobol sequences of seed (seed_hi, seed_lo): the
 * OMC part's. 20 bytes. */
typedef struct {
    u32 seed_lo;
    u32 seed_hi;
    u32 offset;
    u32 step;
    u32 per_round;
} BurnInFilm;

/* The pixels whose Sobol sequences the path tracer begins one number later
 * (cl/kernels/pt.cl): those MLT's burn-in gave one sample more
 * (cl/core/burnin_order.h). Pixel p is one if
 * ((p * inverse) mod P + P - offset) mod P < count; count 0: none. 12 bytes. */
typedef struct {
    u32 offset;
    u32 inverse;
    u32 count;
} LatePixels;

/* A stratum of the film for MLT's chains (cl/sampling/strata.cl): the
 * pixels [x0, x0 + w) x [y0, y0 + h). A chain of the stratum reads its film
 * numbers (u, v) in [0, 1)^2 as the film position (ox + u sx, oy + v sy) and
 * splats to pixel (x0 + floor(u w), y0 + floor(v h)); ox = x0 / width,
 * sx = w / width (and so for y), rounded to float, so that the whole film
 * is ox = oy = 0, sx = sy = 1 exactly. 32 bytes. */
typedef struct {
    u32 x0;
    u32 y0;
    u32 w;
    u32 h;
    f32 ox;
    f32 oy;
    f32 sx;
    f32 sy;
} FilmTile;

/* What a stratum's large steps weigh (cl/mlt/mlt_step.cl). A large step
 * draws its film numbers uniformly on the stratum's pixels where the
 * target's weight is above 0 (the chains' part), by up to
 * MLT_LARGE_FILM_TRIES uniform draws on the whole tile; where all miss it
 * keeps the last, where the target is 0. On the chains' part, a share A of
 * the tile's pixels, its density against the uniform one is then
 * large_density = (1 - (1 - A)^tries) / A (1 where A = 1 or A = 0).
 * kelemen_pb is p b0 large_density, the large steps' density in the balance
 * heuristic of Kelemen's weights (0: expected values alone); a large step
 * adds I(y) / large_density to b's sum. 8 bytes. */
typedef struct {
    f32 kelemen_pb;
    f32 large_density;
} StratumWeights;
#define MLT_LARGE_FILM_TRIES 16u

/* The layout of every struct above, one list: S(struct, size in bytes)
 * and, for each field past the first, F(struct, field, offset in bytes).
 * The host static_asserts it (src/scene/shared_layout.cpp), and the host and
 * a probe kernel (test/cl/probe.cl) both report sizes and offsets in its
 * order for a test to compare. */
/* clang-format off */
#define SHARED_LAYOUT(S, F)                                                                        \
    S(Triangle, 48) F(Triangle, material, 12) F(Triangle, e1, 16)                                  \
        F(Triangle, light_pick_prob, 28) F(Triangle, e2, 32) F(Triangle, light_index, 44)          \
    S(TriangleNormals, 36) F(TriangleNormals, n1, 12) F(TriangleNormals, n2, 24)                 \
    S(BvhNode, 32) F(BvhNode, offset, 12) F(BvhNode, hi, 16) F(BvhNode, count, 28)                 \
    S(Material, 168) F(Material, type, 12) F(Material, ke, 16) F(Material, ior, 28)                 \
        F(Material, ks, 32) F(Material, emissive, 44) F(Material, eta, 48)                         \
        F(Material, alpha, 60) F(Material, k, 64) F(Material, flags, 76)                           \
        F(Material, fdr_int, 80) F(Material, spec_weight, 84) F(Material, kd_tex, 88)              \
        F(Material, ks_tex, 92) F(Material, rough_tex, 96) F(Material, alpha_tex, 100)             \
        F(Material, coat_t, 104)                                                                   \
    S(TextureInfo, 16) F(TextureInfo, width, 4) F(TextureInfo, height, 8) F(TextureInfo, flags, 12) \
    S(TriangleUVs, 24) F(TriangleUVs, uv1, 8) F(TriangleUVs, uv2, 16)                              \
    S(LightEntry, 8) F(LightEntry, cdf_hi, 4)                                                      \
    S(Frame, 64) F(Frame, width, 12) F(Frame, top_left, 16) F(Frame, height, 28)                   \
        F(Frame, du, 32) F(Frame, depth, 44) F(Frame, dv, 48) F(Frame, num_lights, 60)             \
    S(ChainValue, 20) F(ChainValue, meta, 12) F(ChainValue, stay, 16)                              \
    S(FilmShape, 20) F(FilmShape, bands, 4) F(FilmShape, frac_bits, 8) F(FilmShape, scale, 12)     \
        F(FilmShape, layers, 16)                                                                   \
    S(TargetCells, 8) F(TargetCells, columns, 4)                                                   \
    S(BurnInFilm, 20) F(BurnInFilm, seed_hi, 4) F(BurnInFilm, offset, 8)                          \
        F(BurnInFilm, step, 12) F(BurnInFilm, per_round, 16)                                       \
    S(LatePixels, 12) F(LatePixels, inverse, 4) F(LatePixels, count, 8)                            \
    S(FilmTile, 32) F(FilmTile, y0, 4) F(FilmTile, w, 8) F(FilmTile, h, 12) F(FilmTile, ox, 16)   \
        F(FilmTile, oy, 20) F(FilmTile, sx, 24) F(FilmTile, sy, 28)                                \
    S(StratumWeights, 8) F(StratumWeights, large_density, 4)
/* clang-format on */

#define FILM_MAX_BANDS 4

/* Kernel arguments that travel as units, declared once for the host and
 * the kernels (X-macros: each entry is X(element type, name)).
 * SCENE_BUFFERS: the scene's read-only buffers, named as DeviceScene's
 * members; a kernel takes them, then the Frame, as SCENE_ARGS
 * (cl/path/path.cl), and the host binds them as one SceneBuffers
 * (src/device/scene_buffers.hpp). FILM_BANDS: the MLT film's bands, one per
 * FILM_MAX_BANDS, then its FilmShape: FILM_ARGS (cl/mlt/film.cl), bound as
 * one MltFilm (src/render/mlt_film.hpp). */
#define SCENE_BUFFERS(X)                                                                           \
    X(Triangle, tris)                                                                              \
    X(TriangleNormals, normals)                                                                    \
    X(TriangleUVs, uvs)                                                                            \
    X(BvhNode, nodes)                                                                              \
    X(Material, materials) X(LightEntry, lights) X(TextureInfo, textures) X(Texel, texels)
#define FILM_BANDS(X) X(FilmWord, band0) X(FilmWord, band1) X(FilmWord, band2) X(FilmWord, band3)
#define FILM64_FRAC_BITS 24

/* Counters of an MLT render: X(NAME, member, JOIN), one list for the
 * kernels (cl/mlt/mlt_step.cl) and the host (MltStats,
 * src/render/mlt_stats.hpp). A work-group counts in local memory, 32-bit
 * (MLT_COUNTS of them), and each step joins that into its own row of stats,
 * MLT_STAT_COUNT 64-bit words, with plain arithmetic (no 64-bit atomics);
 * the host joins the rows. JOIN is SUM or MAX. The row's last word,
 * MLT_STAT_LARGE_LUM, is the sum of I(y) over large steps in MLT_B_FRAC_BITS
 * fixed point, 64-bit from the start. */
#define MLT_COUNTERS(X)                                                                            \
    X(ACCEPTED, accepted, SUM)                                                                     \
    X(LARGE, large, SUM)                                                                           \
    X(NONFINITE, nonfinite, SUM) /* samples dropped as not finite */                               \
    X(RAYS, rays, SUM)                                                                             \
    X(STUCK, stuck, SUM)         /* chains that rejected stuck_run proposals in a row */           \
    X(ATOMICS, atomics, SUM)     /* atomic operations on global memory by the steps */             \
    X(LONGEST, longest_run, MAX) /* most consecutive rejections of any chain */

#define MLT_STAT_INDEX(NAME, member, JOIN) MLT_STAT_##NAME,
enum { MLT_COUNTERS(MLT_STAT_INDEX) MLT_COUNTS };
#undef MLT_STAT_INDEX
#define MLT_STAT_LARGE_LUM MLT_COUNTS
#define MLT_STAT_COUNT (MLT_COUNTS + 1)

/* Counters of a path-traced render, per work-group of the pixels as above. */
#define PT_STAT_RAYS 0
#define PT_STAT_NONFINITE 1
#define PT_STAT_COUNT 2

/* Fraction bits of the luminance sums that make b (burn-in and large
 * steps): exact, order-free sums, so b and the image stay repeatable for a
 * seed and add up exactly over ranks. One sample adds at most
 * MLT_B_MAX_SAMPLE (larger luminances are clamped: 2^32, far above any
 * scene's; 2^56 in fixed point, so sums have room). */
#define MLT_B_FRAC_BITS 24
#define MLT_B_MAX_SAMPLE 4294967296.0f

#endif
