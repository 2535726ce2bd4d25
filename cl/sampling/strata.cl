/* The strata of stratified MLT (src/render/strata.hpp): a chain lives in one
 * tile of the film (FilmTile, cl/core/shared_types.h) and its film numbers
 * are the tile's own unit square, so every proposal, small or large, lands in
 * the tile and every splat goes to one of its pixels. The whole film is one
 * tile: then a film position is its numbers and nothing changes. */

/* Where a sample lies on the film: its position for the camera, in [0, 1)^2
 * of the whole film, and the pixel it splats to. */
typedef struct {
    float x, y;
    uint pixel;
} FilmPoint;

/* The whole film as a tile. */
inline FilmTile strata_whole(const Frame* frame) {
    FilmTile t = {0u, 0u, frame->width, frame->height, 0.0f, 0.0f, 1.0f, 1.0f};
    return t;
}

/* The film point of numbers (u, v) in [0, 1)^2 of tile t: the pixel is
 * computed from the tile's own numbers, so it never leaves the tile whatever
 * the rounding of the position. */
inline FilmPoint strata_point(const FilmTile* t, const Frame* frame, float u, float v) {
    FilmPoint p;
    p.x = t->ox + u * t->sx;
    p.y = t->oy + v * t->sy;
    uint px = t->x0 + min((uint)(u * (float)t->w), t->w - 1u);
    uint py = t->y0 + min((uint)(v * (float)t->h), t->h - 1u);
    p.pixel = py * frame->width + px;
    return p;
}

/* The tile of `pixel` among the grid's tiles (src/render/strata.cpp,
 * strata_grid): row-major, each as large as the first but the last row and
 * column. */
inline uint strata_pixel_tile(__global const FilmTile* tiles, const Frame* frame, uint pixel) {
    uint sx = tiles[0].w, sy = tiles[0].h, columns = (frame->width + sx - 1u) / sx;
    return pixel / frame->width / sy * columns + pixel % frame->width / sx;
}

/* One of a burn-in sample's `bits`-wide film numbers `g` (of the whole film,
 * along an axis of n pixels) as a number of the tile [x0, x0 + w) on that
 * axis: the tile's grid value nearest below the same position, clamped into
 * the tile (a sample outside it starts at its edge). Exact for the whole
 * film: g n / n = g. */
inline uint strata_local_number(uint g, uint n, uint x0, uint w) {
    long at = (long)((ulong)g * n) - ((long)x0 << LAYOUT_CAMERA_BITS);
    long top = ((long)1 << LAYOUT_CAMERA_BITS) - 1l;
    return (uint)clamp(at / (long)w, 0l, top);
}

/* A burn-in sample's film numbers `film` (whole film) as numbers of tile t. */
inline uint2 strata_local(const FilmTile* t, const Frame* frame, uint2 film) {
    return (uint2)(strata_local_number(film.x, frame->width, t->x0, t->w),
                   strata_local_number(film.y, frame->height, t->y0, t->h));
}
