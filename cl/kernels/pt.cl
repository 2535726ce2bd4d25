/* Entry point of the path tracer (ordinary Monte Carlo). One work-item per
 * pixel; its k-th sample of pixel p reads the numbers of
 * smp_pixel(seed, p, offset + k * stride + late) (cl/sampling/sample_sobol.cl
 * or cl/sampling/sample_omc.cl; offset 0 and stride 1 in one process, rank r
 * of R ranks takes offset r and stride R; late is 1 for the pixels of `late`,
 * whose sequence MLT's burn-in took one number further), so an image depends
 * only on the seed and the sample count, not on how samples are split into
 * passes. The film is in bands (src/device/memory_plan.hpp): this run
 * covers pixels first .. first + count - 1, and `accum` holds their
 * (sum R, sum G, sum B).
 * Each work-group adds its rays and dropped non-finite samples to its row of
 * stats (PT_STAT_*; first is a multiple of the group size).
 * Built with PT_OMC_PART, it renders only the OMC part of the split
 * (cl/path/path.cl), which takes the chains' target (weight, cells): in a
 * cell of weight 0 the whole path (src/render/omc_cells.hpp), elsewhere
 * the terms before PATH_SPLIT vertices, from paths that stop after the
 * PATH_SPLIT - 1 bounces those need. A pass takes either the cells'
 * pixels (cells_only) or the others, each part numbering its own samples
 * (first_sample), so that a pixel's numbers stay consecutive. */

#ifdef PT_OMC_PART
#define PT_OMC_ARGS , __global const float *weight, const TargetCells cells, const uint cells_only
#define PT_WHOLE(pixel) (target_weight(weight, &cells, frame.width, (pixel)) == 0.0f)
#define PT_TAKES(whole) ((cells_only != 0u) == (whole))
#else
#define PT_OMC_ARGS
#define PT_WHOLE(pixel) true
#define PT_TAKES(whole) true
#endif

__kernel void pt_render(SCENE_ARGS, const ulong seed, const uint first_sample, const uint spp,
                        const uint offset, const uint stride, const LatePixels late,
                        const uint first, const uint count, __global float* accum,
                        __global ulong* stats PT_OMC_ARGS) {
    __local uint l_rays, l_nonfinite;
    if (get_local_id(0) == 0u) l_rays = l_nonfinite = 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    uint i = get_global_id(0);
    if (i < count) {
        uint pixel = first + i;
        SceneView sc = SCENE_VIEW();
        const bool whole = PT_WHOLE(pixel);
        if (!whole) sc.depth = min(sc.depth, (uint)(PATH_SPLIT - 1));
        float px = (float)(pixel % frame.width), py = (float)(pixel / frame.width);
        float3 acc = vload3(i, accum);
        uint rays = 0u, nonfinite = 0u;
        uint start = offset + burnin_order_late(&late, frame.width * frame.height, pixel);
        const uint n = PT_TAKES(whole) ? spp : 0u;
        for (uint s = 0; s < n; ++s) {
            SampleSource src = smp_pixel(seed, pixel, start + (first_sample + s) * stride);
            float fx = (px + smp_uniform(&src, 0u, layout_film(0u))) / (float)frame.width;
            float fy = (py + smp_uniform(&src, 0u, layout_film(1u))) / (float)frame.height;
            PathResult r = path_trace(&sc, &src, camera_ray(&frame, fx, fy));
            float3 v = whole ? path_radiance(&r) : r.omc;
            if (path_finite(v))
                acc += v;
            else
                ++nonfinite;
            rays += r.rays;
        }
        vstore3(acc, i, accum);
        atomic_add(&l_rays, rays);
        if (nonfinite) atomic_add(&l_nonfinite, nonfinite);
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    if (get_local_id(0) != 0u) return;
    __global ulong* row =
        stats + (size_t)(first / get_local_size(0) + get_group_id(0)) * PT_STAT_COUNT;
    row[PT_STAT_RAYS] += l_rays;
    row[PT_STAT_NONFINITE] += l_nonfinite;
}
