/* The MLT film on the device. A splat may land on any pixel, so every band
 * of the film is bound at once: up to FILM_MAX_BANDS buffers, each within
 * the device's largest allocation (FilmShape in cl/core/shared_types.h). Words
 * are 32-bit fixed point added by 32-bit atomics (core OpenCL 1.1); the host
 * drains them into its 64-bit film before any word could overflow
 * (src/render/mlt_film.hpp states and proves the bound). Values are rounded
 * up or down at random, with the probability of their fraction, from the
 * numbers of the step's stream: rounding adds noise, never bias, and a seed
 * still gives one image. FILM_ATOMICS64, the reference build, keeps one
 * 64-bit band with FILM64_FRAC_BITS, rounded to nearest (it needs
 * cl_khr_int64_base_atomics). */

#ifdef FILM_ATOMICS64
#pragma OPENCL EXTENSION cl_khr_int64_base_atomics : enable
typedef ulong FilmWord;
#else
typedef uint FilmWord;
#endif

#define FILM_MEMBER(T, name) __global T* name;
#define FILM_PARAM(T, name) __global T *name,
#define FILM_NAME(T, name) name,

typedef struct {
    FILM_BANDS(FILM_MEMBER)
    FilmShape shape;
} Film;

/* The film as a kernel's parameters (FILM_BANDS, then the shape), and the
 * Film of a kernel that took them. */
#define FILM_ARGS FILM_BANDS(FILM_PARAM) const FilmShape film_shape
#define FILM_VIEW() ((Film){FILM_BANDS(FILM_NAME) film_shape})

#if FILM_MAX_BANDS != 4
#error "film_words picks among 4 bands: extend it with FILM_BANDS"
#endif

/* The three words of a pixel's layer. */
inline __global FilmWord* film_words(const Film* film, uint pixel, uint layer) {
    uint band = pixel / film->shape.band_pixels;
    uint at = 3u * ((pixel - band * film->shape.band_pixels) * film->shape.layers + layer);
    if (band == 0u) return film->band0 + at;
    if (band == 1u) return film->band1 + at;
    return (band == 2u ? film->band2 : film->band3) + at;
}

/* v >= 0 in units of the word, rounded by u in [0, 1): up with the
 * probability of v's fraction, else down (to nearest in the reference
 * build). The fraction is taken exactly: (uint)(v + u) would round v + u
 * to float first, up more often than down once v's spacing nears 1. */
inline FilmWord film_round(float v, float u) {
#ifdef FILM_ATOMICS64
    return (FilmWord)(v + 0.5f);
#else
    float whole = floor(v);
    return (FilmWord)whole + (v - whole > u ? 1u : 0u);
#endif
}

/* w * f / lum(f) in the film's units, per channel, rounded with the numbers
 * dim .. dim + 2 of key's stream; false if it adds nothing. */
inline bool film_value(const Film* film, float3 f, float w, ulong key, uint dim, FilmWord* c) {
    float lum = path_luminance(f);
    if (!(w > 0.0f) || !(lum > 0.0f)) return false;
    float3 v = f * (w / lum) * film->shape.scale;
    c[0] = film_round(v.x, rng_unit(key, dim));
    c[1] = film_round(v.y, rng_unit(key, dim + 1u));
    c[2] = film_round(v.z, rng_unit(key, dim + 2u));
    return true;
}

inline void film_atomic_add(__global FilmWord* word, FilmWord v) {
#ifdef FILM_ATOMICS64
    atom_add(word, v);
#else
    atomic_add(word, v);
#endif
}

/* Adds w * f / lum(f) to a pixel's layer (subtracts it with `undo`,
 * exactly, given the same key); returns the global atomics it made. */
inline uint film_splat(const Film* film, uint pixel, uint layer, float3 f, float w, ulong key,
                       uint dim, bool undo) {
    FilmWord c[3];
    if (!film_value(film, f, w, key, dim, c)) return 0u;
    __global FilmWord* words = film_words(film, pixel, layer);
    uint n = 0u;
    for (uint i = 0; i < 3u; ++i)
        if (c[i]) {
            film_atomic_add(&words[i], undo ? (FilmWord)0 - c[i] : c[i]);
            ++n;
        }
    return n;
}
