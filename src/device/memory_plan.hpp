// The one place that knows every device buffer a render allocates and its
// size, as a function of the scene, film, depth, thread count N and proposals
// per chain K. The renderers allocate with these sizes; ClContext counts what
// was allocated, and tests compare the two.
#pragma once
#include "device/ocl.hpp"
#include "scene/device_scene.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace smallmlt {

// Every kind of device buffer a render allocates: X(Enum, name). The
// burn-in's (luminance, OMC samples) are freed once the
// chains have started, but counted as held at once: total() is the peak.
#define SMALLMLT_BUFFERS(X)                                                                        \
    X(Triangles, "triangles")                                                                      \
    X(Normals, "normals")                                                                          \
    X(Uvs, "texture coordinates")                                                                  \
    X(Textures, "texture table")                                                                   \
    X(Texels, "texels")                                                                            \
    X(Bvh, "bvh")                                                                                  \
    X(Materials, "materials")                                                                      \
    X(Lights, "lights")                                                                            \
    X(State, "state")                                                                              \
    X(Values, "values")                                                                            \
    X(FilmBand, "film band")                                                                       \
    X(Stats, "stats")                                                                              \
    X(Picks, "picks")                                                                              \
    X(TargetWeights, "target weights")                                                             \
    X(StrataTiles, "strata tiles")                                                                 \
    X(StrataWeights, "strata weights")                                                             \
    X(GroupTiles, "group tiles")                                                                   \
    X(Luminance, "luminance")                                                                      \
    X(OmcScratchBand, "OMC scratch band")                                                          \
    X(OmcStats, "OMC stats")                                                                       \
    X(OmcSamples, "OMC samples")

#define SMALLMLT_BUFFER_ENUM(e, name) e,
enum class Buffer { SMALLMLT_BUFFERS(SMALLMLT_BUFFER_ENUM) };
#undef SMALLMLT_BUFFER_ENUM

const char* buffer_name(Buffer b);

struct PlannedBuffer {
    Buffer kind;
    std::uint32_t band = 0;   // of a FilmBand
    std::uint64_t bytes;      // as allocated (device_alloc_bytes)
    std::string name() const; // buffer_name, and a film band's number
};

struct MemoryPlan {
    std::vector<PlannedBuffer> buffers;
    std::uint64_t total() const;               // all at once: the peak of a render
    std::uint64_t largest() const;             // the biggest single buffer
    std::uint64_t bytes(Buffer kind) const;    // requested size (0 if empty)
    std::uint64_t sum(bool chain_state) const; // chain state buffers or the rest
    std::uint64_t film() const;                // the film's bands
    std::uint32_t film_bands() const;          // how many there are
};

// What a render stores per chain and how many chains it has.
struct ChainShape {
    std::uint32_t threads = 1u << 16;
    std::uint32_t proposals = 1; // K: threads per chain
    bool float32_states = false;
    bool film_atomics64 = false;    // the 64-bit reference film (MltOptions)
    bool omc_part = false;          // a split: the OMC part's film and counters too
    std::uint32_t target_cells = 1; // weights of the chains' target (src/render/target.hpp)
    std::uint32_t film_layers = 1;  // 2 with Kelemen's weights: the large steps' own
    bool strata = false;            // stratified MLT: up to a tile per work-group
    std::uint32_t chains() const { return threads / proposals; }
};

// Throws UsageError unless K is a power of two up to kDefaultWorkGroup (a
// chain's K work-items meet in one work-group) and divides the threads.
void check_chain_shape(const ChainShape& shape);

// A film of `pixels` split into bands that each fit one allocation: every
// band but the last holds band_pixels, a multiple of kDefaultWorkGroup
// (a work-group's pixels never straddle two bands). Throws InputError if
// the largest allocation cannot hold one work-group's pixels.
struct FilmBands {
    std::uint64_t band_pixels = 0;
    std::uint32_t bands = 0;
};
FilmBands film_bands(std::uint64_t pixels, std::uint64_t bytes_per_pixel, std::uint64_t max_alloc);

constexpr std::uint64_t kNoAllocLimit = ~std::uint64_t(0);

// Bytes per pixel of the films on the device.
constexpr std::uint64_t kPtFilmPixelBytes = 3 * sizeof(float);

// Pixels of the OMC part's scratch band (a split; src/render/path_tracer.hpp):
// at most 16,384 (192 KiB), a multiple of the work-group.
std::uint64_t omc_scratch_pixels(std::uint64_t pixels);
// Bytes per pixel of the MLT film: three words per layer, 4 B each (8 B in
// the 64-bit reference film).
std::uint64_t mlt_film_pixel_bytes(bool atomics64, std::uint32_t layers);

// Every buffer of a render whose film's bands fit max_alloc bytes each.
MemoryPlan plan_pt(const DeviceScene& ds, std::uint64_t max_alloc = kNoAllocLimit);
MemoryPlan plan_mlt(const DeviceScene& ds, const ChainShape& shape,
                    std::uint64_t max_alloc = kNoAllocLimit);

// What the render may use: the device's memory (or --device-mem) and its
// largest single allocation.
struct DeviceBudget {
    std::uint64_t global_bytes = 0, max_alloc_bytes = 0;
    bool emulated = false; // from --device-mem
};

// A render may use this fraction of device memory (the rest is left to the
// driver, the display and other programs).
constexpr double kMemoryFraction = 0.5;
constexpr std::uint32_t kMinThreads = 64; // one work-group: the smallest useful render
// The scene's textures may take this fraction of device memory, and no more
// than the largest allocation (they are one buffer): the rest is the render's.
constexpr double kTextureFraction = 0.25;

// --device-mem B emulates a device of B bytes (never more than the real one)
// whose largest allocation is B / 4, the least OpenCL allows.
DeviceBudget device_budget(const DeviceInfo& dev, std::optional<std::uint64_t> device_mem);

// The bytes of texels a scene may keep on the device (kTextureFraction).
std::uint64_t texture_budget(const DeviceBudget& b);

bool plan_fits(const MemoryPlan& plan, const DeviceBudget& b);

// The smallest device memory M on which the plan that plan_at(M / 4) gives
// fits, M / 4 being the largest allocation --device-mem M emulates (the
// least OpenCL allows). plan_at may throw InputError (too small to split).
std::uint64_t smallest_device_memory(const std::function<MemoryPlan(std::uint64_t)>& plan_at);

// Throws InputError naming the device if its work-groups cannot hold
// kDefaultWorkGroup work-items, the size every kernel runs in.
void require_work_group(const DeviceInfo& dev);

// Threads that keep the device busy: on a GPU, 8 work-groups of the largest
// size per compute unit; on a CPU, kCpuThreadsPerCore per core, the
// fewer of its compute units and this machine's hardware threads (its
// throughput is flat in N, doc/RESULTS.md, and fewer chains run longer);
// rounded up to a power of two, within [2^10, 2^20].
constexpr std::uint64_t kCpuThreadsPerCore = 8192;
std::uint32_t busy_threads(const DeviceInfo& dev);

struct ThreadChoice {
    std::uint32_t threads = 0;
    std::uint32_t reduction = 1; // busy_threads / threads
    MemoryPlan plan;
};

// --threads auto: busy_threads halved until the plan fits. Throws
// InputError, naming the smallest device memory that would do, when not even
// kMinThreads fit.
ThreadChoice choose_threads(const DeviceScene& ds, ChainShape shape, const DeviceInfo& dev,
                            const DeviceBudget& budget);

// --threads N given: throws UsageError naming the largest N that fits if it
// does not.
MemoryPlan check_threads(const DeviceScene& ds, const ChainShape& shape,
                         const DeviceBudget& budget);

// The largest thread count up to shape.threads whose render fits (0 if not
// even kMinThreads do). Any count fits, not only the powers of two that
// --threads auto tries.
std::uint32_t max_threads(const DeviceScene& ds, ChainShape shape, const DeviceBudget& budget);

// "12.3 MiB"
std::string format_bytes(std::uint64_t bytes);

} // namespace smallmlt
