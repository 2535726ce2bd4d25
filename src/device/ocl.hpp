// OpenCL host plumbing: checked calls that report file, line and the error's
// name; device discovery; program builds from the embedded kernel sources.
#pragma once
#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace smallmlt {

const char* cl_error_name(cl_int err);

// Throws InputError "file:line: what failed: CL_ERROR_NAME".
void cl_check(cl_int err, const char* what, const char* file, int line);

// Where an embedded file starts in a program's joined source (1-based line).
struct SourceStart {
    std::string file;
    int first_line;
};

// A build log with "<kernel>:N:" (compilers that ignore #line, such as
// NVIDIA's) rewritten as "cl/<stage>/<file>.cl:M:", M the line within that file.
std::string cl_name_log_lines(const std::string& log, const std::vector<SourceStart>& starts);

#define CL_CHECK(call) ::smallmlt::cl_check((call), #call, __FILE__, __LINE__)

struct DeviceInfo {
    cl_platform_id platform = nullptr;
    cl_device_id id = nullptr;
    std::string platform_name, name, version, c_version;
    std::uint64_t global_mem_bytes = 0, max_alloc_bytes = 0, local_mem_bytes = 0;
    std::uint32_t compute_units = 0;
    std::size_t max_work_group = 0;
    bool int64_atomics = false;
    bool cpu = false; // CL_DEVICE_TYPE_CPU: its compute units are cores
    // Loop iterations (back edges of all loops together) after which the
    // compiler ends every loop of a work-item early, 0: none. Mesa's llvmpipe
    // (gallivm) stops each invocation at 65,535, so on it a launch must be
    // one path per work-item (cl_loop_iteration_limit).
    std::uint32_t loop_iteration_limit = 0;
    bool emulated = false; // limited by --profile or --device-mem (src/device/device_profile.hpp)
};

// The loop limit of a device by its name (DeviceInfo::loop_iteration_limit).
std::uint32_t cl_loop_iteration_limit(const std::string& device_name);

// Every device of every platform, in a stable order (the --device index).
std::vector<DeviceInfo> cl_list_devices();

// Owns a context and an in-order queue on one device.
class ClContext {
  public:
    explicit ClContext(int device_index = 0);
    ~ClContext();
    ClContext(const ClContext&) = delete;
    ClContext& operator=(const ClContext&) = delete;

    const DeviceInfo& device() const { return info_; }
    // From now on the device counts as `limited` (the same device with
    // smaller figures, emulate_profile): budgets follow its memory, and a
    // program built for a device without cl_khr_int64_base_atomics fails to
    // compile if it uses a 64-bit atomic.
    void emulate(const DeviceInfo& limited);
    cl_context context() const { return ctx_; }
    cl_command_queue queue() const { return queue_; }

    // Device memory held by ClBuffers of this context now, and the most held
    // at once since the last reset_peak (src/device/memory_plan.cpp predicts it).
    std::uint64_t live_bytes() const { return live_bytes_; }
    std::uint64_t peak_bytes() const { return peak_bytes_; }
    void reset_peak() const { peak_bytes_ = live_bytes_; }
    void count_alloc(std::int64_t bytes) const;
    // Waits for all queued work; throws naming `what` if it failed.
    void finish(const std::string& what) const;

    // Builds a program from embedded kernel files (names as "cl/core/rng.h"),
    // joined in order, each preceded by a #line directive naming it, after
    // `defines`. A failed build throws with the compiler's log.
    cl_program build(const std::vector<std::string>& files, const std::string& defines) const;

  private:
    DeviceInfo info_;
    cl_context ctx_ = nullptr;
    cl_command_queue queue_ = nullptr;
    mutable std::uint64_t live_bytes_ = 0, peak_bytes_ = 0;
};

// Bytes a ClBuffer of `bytes` takes on the device: OpenCL has no empty
// buffers, so an empty one takes 16.
inline std::uint64_t device_alloc_bytes(std::uint64_t bytes) {
    return bytes ? bytes : 16;
}

// A device buffer released on destruction.
class ClBuffer {
  public:
    ClBuffer() = default;
    ClBuffer(const ClContext& cl, cl_mem_flags flags, std::size_t bytes,
             const void* host = nullptr);
    ~ClBuffer();
    ClBuffer(ClBuffer&& o) noexcept;
    ClBuffer& operator=(ClBuffer&& o) noexcept;
    ClBuffer(const ClBuffer&) = delete;
    ClBuffer& operator=(const ClBuffer&) = delete;

    cl_mem get() const { return mem_; }
    std::size_t bytes() const { return bytes_; }
    void read(const ClContext& cl, void* dst) const;
    void write(const ClContext& cl, const void* src) const;
    void fill_zero(const ClContext& cl) const;

  private:
    const ClContext* cl_ = nullptr;
    cl_mem mem_ = nullptr;
    std::size_t bytes_ = 0;
};

constexpr std::size_t kDefaultWorkGroup = 64;

// A kernel released on destruction, with typed argument setting.
class ClKernel {
  public:
    ClKernel(cl_program program, const char* name);
    ~ClKernel();
    ClKernel(const ClKernel&) = delete;
    ClKernel& operator=(const ClKernel&) = delete;

    // Sets every argument of the kernel in order: a buffer or a value per
    // argument, or a unit that sets several (an overload of kernel_arg:
    // SceneBuffers, MltFilm). Throws std::logic_error naming the kernel if
    // the arguments set are not as many as it takes.
    template <typename... Args> void set_args(const Args&... args) {
        cl_uint i = 0;
        (kernel_arg(*this, i, args), ...);
        check_arg_count(i);
    }
    void set_arg(cl_uint i, const ClBuffer& b);
    template <typename T> void set_arg(cl_uint i, const T& v) {
        static_assert(std::is_trivially_copyable_v<T>, "a kernel argument is plain data");
        set_raw(i, sizeof(T), &v);
    }
    // Runs over `items` work-items (rounded up to whole work-groups of
    // `local`) and waits for it to finish.
    void run(const ClContext& cl, std::size_t items, std::size_t local = kDefaultWorkGroup) const;
    // Queues a run without waiting; errors surface at the next run or finish.
    void enqueue(const ClContext& cl, std::size_t items,
                 std::size_t local = kDefaultWorkGroup) const;
    cl_kernel get() const { return k_; }
    const std::string& name() const { return name_; }

  private:
    void set_raw(cl_uint i, std::size_t bytes, const void* v);
    void check_arg_count(cl_uint set) const;
    cl_kernel k_ = nullptr;
    cl_uint num_args_ = 0;
    std::string name_;
};

// Sets argument i of k to v and moves i past it; units of several arguments
// overload this.
template <typename T> void kernel_arg(ClKernel& k, cl_uint& i, const T& v) {
    k.set_arg(i++, v);
}

// Releases a program on destruction.
struct ClProgram {
    cl_program p = nullptr;
    explicit ClProgram(cl_program prog) : p(prog) {}
    ~ClProgram();
    ClProgram(const ClProgram&) = delete;
    ClProgram& operator=(const ClProgram&) = delete;
};

} // namespace smallmlt
