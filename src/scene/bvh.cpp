// Binned SAH BVH (after Wald 2007): at each node, centroids are binned into
// kBins slabs along each axis and the split minimizing the surface area
// heuristic is taken, unless a leaf is cheaper.
#include "scene/bvh.hpp"

#include <algorithm>
#include <limits>

namespace smallmlt {

namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kLeafMax = 4;     // a leaf with this many or fewer is always made
constexpr std::uint32_t kLeafForced = 16; // largest leaf made when no split pays off
constexpr float kTraversalCost = 1.0f;    // relative to one ray/triangle test

struct Box {
    Vec3 lo{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
            std::numeric_limits<float>::max()};
    Vec3 hi{-std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
            -std::numeric_limits<float>::max()};
    void grow(Vec3 p) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    void grow(const Box& b) {
        lo = vmin(lo, b.lo);
        hi = vmax(hi, b.hi);
    }
    float area() const {
        if (hi.x < lo.x) return 0.0f;
        Vec3 d = hi - lo;
        return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

struct Builder {
    std::vector<Box> boxes;
    std::vector<Vec3> centroids;
    Bvh out;

    std::uint32_t emit(const Box& b, std::uint32_t offset, std::uint32_t count) {
        BvhNode n{};
        n.lo[0] = b.lo.x, n.lo[1] = b.lo.y, n.lo[2] = b.lo.z;
        n.hi[0] = b.hi.x, n.hi[1] = b.hi.y, n.hi[2] = b.hi.z;
        n.offset = offset;
        n.count = count;
        out.nodes.push_back(n);
        return static_cast<std::uint32_t>(out.nodes.size() - 1);
    }

    // Chooses a split of order[begin, end): returns the middle index, or
    // `begin` when a leaf is better.
    std::uint32_t split(std::uint32_t begin, std::uint32_t end, const Box& box) {
        std::uint32_t count = end - begin;
        Box cbox;
        for (std::uint32_t i = begin; i < end; ++i)
            cbox.grow(centroids[out.order[i]]);
        float best_cost = std::numeric_limits<float>::max();
        int best_axis = -1, best_bin = 0;
        for (int axis = 0; axis < 3; ++axis) {
            float lo = cbox.lo[axis], ext = cbox.hi[axis] - lo;
            if (!(ext > 0)) continue;
            Box bins[kBins];
            std::uint32_t counts[kBins] = {};
            for (std::uint32_t i = begin; i < end; ++i) {
                std::uint32_t t = out.order[i];
                int b =
                    std::min(kBins - 1, static_cast<int>((centroids[t][axis] - lo) / ext * kBins));
                bins[b].grow(boxes[t]);
                ++counts[b];
            }
            float right_area[kBins];
            std::uint32_t right_count[kBins];
            Box acc;
            std::uint32_t n = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc.grow(bins[b]);
                n += counts[b];
                right_area[b] = acc.area();
                right_count[b] = n;
            }
            acc = Box();
            n = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                acc.grow(bins[b]);
                n += counts[b];
                if (n == 0 || right_count[b + 1] == 0) continue;
                float cost = acc.area() * n + right_area[b + 1] * right_count[b + 1];
                if (cost < best_cost) best_cost = cost, best_axis = axis, best_bin = b;
            }
        }
        float leaf_cost = static_cast<float>(count);
        float split_cost = kTraversalCost + best_cost / std::max(box.area(), 1e-30f);
        if (best_axis < 0) return count <= kLeafForced ? begin : begin + count / 2;
        if (split_cost >= leaf_cost && count <= kLeafForced) return begin;
        float lo = cbox.lo[best_axis], ext = cbox.hi[best_axis] - lo;
        auto mid = std::partition(
            out.order.begin() + begin, out.order.begin() + end, [&](std::uint32_t t) {
                int b = std::min(kBins - 1,
                                 static_cast<int>((centroids[t][best_axis] - lo) / ext * kBins));
                return b <= best_bin;
            });
        return static_cast<std::uint32_t>(mid - out.order.begin());
    }

    void build(std::uint32_t begin, std::uint32_t end, int depth) {
        out.depth = std::max(out.depth, depth);
        Box box;
        for (std::uint32_t i = begin; i < end; ++i)
            box.grow(boxes[out.order[i]]);
        std::uint32_t count = end - begin;
        std::uint32_t mid = begin;
        if (count > kLeafMax && depth < kBvhMaxDepth) mid = split(begin, end, box);
        if (mid == begin || mid == end) {
            emit(box, begin, count);
            return;
        }
        std::uint32_t self = emit(box, 0, 0);
        build(begin, mid, depth + 1);
        out.nodes[self].offset = static_cast<std::uint32_t>(out.nodes.size());
        build(mid, end, depth + 1);
    }
};

} // namespace

Bvh bvh_build(const std::vector<SceneTriangle>& tris) {
    Builder b;
    b.boxes.resize(tris.size());
    b.centroids.resize(tris.size());
    b.out.order.resize(tris.size());
    for (std::size_t i = 0; i < tris.size(); ++i) {
        for (const Vec3& v : tris[i].v)
            b.boxes[i].grow(v);
        b.centroids[i] = (tris[i].v[0] + tris[i].v[1] + tris[i].v[2]) * (1.0f / 3.0f);
        b.out.order[i] = static_cast<std::uint32_t>(i);
    }
    b.build(0, static_cast<std::uint32_t>(tris.size()), 1);
    return std::move(b.out);
}

} // namespace smallmlt
