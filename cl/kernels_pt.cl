/* Entry point of the path tracer (ordinary Monte Carlo). One work-item per
 * pixel; sample s of pixel p reads the numbers of smp_pixel(seed, p, s)
 * (cl/sample_sobol.cl or cl/sample_omc.cl), so an image
 * depends only on the seed and the sample count, not on how samples are split
 * into passes. accum holds per pixel (sum R, sum G, sum B, number of
 * non-finite samples dropped). */

__kernel void pt_render(__global const Triangle* tris, __global const BvhNode* nodes,
                        __global const Material* mats, __global const LightEntry* lights,
                        const Frame frame, const ulong seed, const uint first_sample,
                        const uint spp, __global float4* accum, __global ulong* ray_count) {
    uint pixel = get_global_id(0);
    if (pixel >= frame.width * frame.height) return;
    SceneView sc = path_scene(tris, nodes, mats, lights, &frame);
    float px = (float)(pixel % frame.width), py = (float)(pixel / frame.width);
    float4 acc = accum[pixel];
    uint rays = 0;
    for (uint s = 0; s < spp; ++s) {
        SampleSource src = smp_pixel(seed, pixel, first_sample + s);
        float fx = (px + smp_uniform(&src, 0u, layout_film(0u))) / (float)frame.width;
        float fy = (py + smp_uniform(&src, 0u, layout_film(1u))) / (float)frame.height;
        PathResult r = path_trace(&sc, &src, camera_ray(&frame, fx, fy));
        acc +=
            path_finite(r.radiance) ? (float4)(r.radiance, 0.0f) : (float4)(0.0f, 0.0f, 0.0f, 1.0f);
        rays += r.rays;
    }
    accum[pixel] = acc;
    ray_count[pixel] += rays;
}
