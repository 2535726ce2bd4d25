/* The emission the camera sees directly (the split's OMC part, src/render/
 * split.hpp), by sampling the emitters from the eye as next-event
 * estimation samples them from a vertex (src/render/emission_seen.hpp). */

/* A light picked by power through the CDF's 2^pick_bits grid and a point
 * uniformly on it, from the numbers of stream `key`. Where that point faces
 * the eye, nothing blocks it (smooth transmitters do) and it lies on the
 * film: (Y^2 n / pdf_w, Y, the pixel's bits, 0), Y the light's luminance
 * and n the film's pixels per steradian, an estimate of the sum over pixels
 * of E[Y^2] of one camera sample. Else 0. */
float4 emission_seen_sample(const SceneView* sc, const Frame* frame, ulong key, uint pick_bits) {
    uint pick = light_pick(sc->lights, sc->num_lights,
                           pick_bits ? rng_u32(key, 0u) >> (32u - pick_bits) : 0u);
    float u1 = rng_unit(key, 1u), u2 = rng_unit(key, 2u);
    float3 eye = (float3)(frame->eye[0], frame->eye[1], frame->eye[2]);
    LightSample ls;
    float2 film;
    float n;
    if (!light_sample_tri(&sc->tris[sc->lights[pick].triangle], sc->mats, eye, u1, u2, &ls) ||
        !camera_film_position(frame, ls.wi, &film, &n))
        return (float4)(0.0f);
    Ray ray;
    ray.o = eye;
    ray.d = ls.wi;
    ray.tmax = ls.dist * (1.0f - 1e-4f);
    uint rays = 0u;
    if (path_shadow(sc, ray, &rays) != PATH_LIT) return (float4)(0.0f);
    uint px = min((uint)(film.x * (float)frame->width), frame->width - 1u);
    uint py = min((uint)(film.y * (float)frame->height), frame->height - 1u);
    float y = path_luminance(ls.radiance);
    return (float4)(y * y * n / ls.pdf_w, y, as_float(py * frame->width + px), 0.0f);
}
