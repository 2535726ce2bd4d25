/* Test probe of the Sobol sample source (cl/sampling/sample_sobol.cl): work-item
 * i < n writes the numbers of slots `slot` and `slot` + 1 of `bounce` (or the film
 * position when bounce is ~0u) for sample first + i of pixel `pixel`. */

__kernel void probe_sobol(const ulong seed, const uint pixel, const uint first, const uint n,
                          const uint bounce, const uint slot, __global float2* out) {
    uint i = get_global_id(0);
    if (i >= n) return;
    SampleSource src = smp_pixel(seed, pixel, first + i);
    if (bounce == ~0u) {
        out[i] = (float2)(smp_uniform(&src, 0u, layout_film(0u)),
                          smp_uniform(&src, 0u, layout_film(1u)));
        return;
    }
#if LAYOUT_BOUNCE_DIMS > 0
    out[i] = (float2)(smp_uniform(&src, bounce, layout_slot(bounce, (int)slot)),
                      smp_uniform(&src, bounce, layout_slot(bounce, (int)slot + 1)));
#endif
}
