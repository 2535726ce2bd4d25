#include "device/ocl.hpp"

#include "base/error.hpp"
#include "base/interrupt.hpp"
#include "device/kernel_sources.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace smallmlt {

const char* cl_error_name(cl_int err) {
    switch (err) {
#define SMALLMLT_CL_ERR(e)                                                                         \
    case e:                                                                                        \
        return #e;
        SMALLMLT_CL_ERR(CL_SUCCESS)
        SMALLMLT_CL_ERR(CL_DEVICE_NOT_FOUND)
        SMALLMLT_CL_ERR(CL_DEVICE_NOT_AVAILABLE)
        SMALLMLT_CL_ERR(CL_COMPILER_NOT_AVAILABLE)
        SMALLMLT_CL_ERR(CL_MEM_OBJECT_ALLOCATION_FAILURE)
        SMALLMLT_CL_ERR(CL_OUT_OF_RESOURCES)
        SMALLMLT_CL_ERR(CL_OUT_OF_HOST_MEMORY)
        SMALLMLT_CL_ERR(CL_PROFILING_INFO_NOT_AVAILABLE)
        SMALLMLT_CL_ERR(CL_MEM_COPY_OVERLAP)
        SMALLMLT_CL_ERR(CL_IMAGE_FORMAT_MISMATCH)
        SMALLMLT_CL_ERR(CL_IMAGE_FORMAT_NOT_SUPPORTED)
        SMALLMLT_CL_ERR(CL_BUILD_PROGRAM_FAILURE)
        SMALLMLT_CL_ERR(CL_MAP_FAILURE)
        SMALLMLT_CL_ERR(CL_MISALIGNED_SUB_BUFFER_OFFSET)
        SMALLMLT_CL_ERR(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST)
        SMALLMLT_CL_ERR(CL_COMPILE_PROGRAM_FAILURE)
        SMALLMLT_CL_ERR(CL_LINKER_NOT_AVAILABLE)
        SMALLMLT_CL_ERR(CL_LINK_PROGRAM_FAILURE)
        SMALLMLT_CL_ERR(CL_DEVICE_PARTITION_FAILED)
        SMALLMLT_CL_ERR(CL_KERNEL_ARG_INFO_NOT_AVAILABLE)
        SMALLMLT_CL_ERR(CL_INVALID_VALUE)
        SMALLMLT_CL_ERR(CL_INVALID_DEVICE_TYPE)
        SMALLMLT_CL_ERR(CL_INVALID_PLATFORM)
        SMALLMLT_CL_ERR(CL_INVALID_DEVICE)
        SMALLMLT_CL_ERR(CL_INVALID_CONTEXT)
        SMALLMLT_CL_ERR(CL_INVALID_QUEUE_PROPERTIES)
        SMALLMLT_CL_ERR(CL_INVALID_COMMAND_QUEUE)
        SMALLMLT_CL_ERR(CL_INVALID_HOST_PTR)
        SMALLMLT_CL_ERR(CL_INVALID_MEM_OBJECT)
        SMALLMLT_CL_ERR(CL_INVALID_IMAGE_FORMAT_DESCRIPTOR)
        SMALLMLT_CL_ERR(CL_INVALID_IMAGE_SIZE)
        SMALLMLT_CL_ERR(CL_INVALID_SAMPLER)
        SMALLMLT_CL_ERR(CL_INVALID_BINARY)
        SMALLMLT_CL_ERR(CL_INVALID_BUILD_OPTIONS)
        SMALLMLT_CL_ERR(CL_INVALID_PROGRAM)
        SMALLMLT_CL_ERR(CL_INVALID_PROGRAM_EXECUTABLE)
        SMALLMLT_CL_ERR(CL_INVALID_KERNEL_NAME)
        SMALLMLT_CL_ERR(CL_INVALID_KERNEL_DEFINITION)
        SMALLMLT_CL_ERR(CL_INVALID_KERNEL)
        SMALLMLT_CL_ERR(CL_INVALID_ARG_INDEX)
        SMALLMLT_CL_ERR(CL_INVALID_ARG_VALUE)
        SMALLMLT_CL_ERR(CL_INVALID_ARG_SIZE)
        SMALLMLT_CL_ERR(CL_INVALID_KERNEL_ARGS)
        SMALLMLT_CL_ERR(CL_INVALID_WORK_DIMENSION)
        SMALLMLT_CL_ERR(CL_INVALID_WORK_GROUP_SIZE)
        SMALLMLT_CL_ERR(CL_INVALID_WORK_ITEM_SIZE)
        SMALLMLT_CL_ERR(CL_INVALID_GLOBAL_OFFSET)
        SMALLMLT_CL_ERR(CL_INVALID_EVENT_WAIT_LIST)
        SMALLMLT_CL_ERR(CL_INVALID_EVENT)
        SMALLMLT_CL_ERR(CL_INVALID_OPERATION)
        SMALLMLT_CL_ERR(CL_INVALID_GL_OBJECT)
        SMALLMLT_CL_ERR(CL_INVALID_BUFFER_SIZE)
        SMALLMLT_CL_ERR(CL_INVALID_MIP_LEVEL)
        SMALLMLT_CL_ERR(CL_INVALID_GLOBAL_WORK_SIZE)
        SMALLMLT_CL_ERR(CL_INVALID_PROPERTY)
        SMALLMLT_CL_ERR(CL_INVALID_IMAGE_DESCRIPTOR)
        SMALLMLT_CL_ERR(CL_INVALID_COMPILER_OPTIONS)
        SMALLMLT_CL_ERR(CL_INVALID_LINKER_OPTIONS)
        SMALLMLT_CL_ERR(CL_INVALID_DEVICE_PARTITION_COUNT)
#undef SMALLMLT_CL_ERR
    case -1001:
        return "CL_PLATFORM_NOT_FOUND_KHR";
    default:
        return "unknown OpenCL error";
    }
}

void cl_check(cl_int err, const char* what, const char* file, int line) {
    if (err == CL_SUCCESS) return;
    std::ostringstream msg;
    msg << file << ":" << line << ": " << what << " failed: " << cl_error_name(err) << " (" << err
        << ")";
    throw InputError(msg.str());
}

namespace {

std::string device_string(cl_device_id d, cl_device_info what) {
    std::size_t n = 0;
    CL_CHECK(clGetDeviceInfo(d, what, 0, nullptr, &n));
    std::string s(n, '\0');
    CL_CHECK(clGetDeviceInfo(d, what, n, s.data(), nullptr));
    while (!s.empty() && (s.back() == '\0' || s.back() == ' '))
        s.pop_back();
    return s;
}

template <typename T> T device_value(cl_device_id d, cl_device_info what) {
    T v{};
    CL_CHECK(clGetDeviceInfo(d, what, sizeof(T), &v, nullptr));
    return v;
}

} // namespace

std::uint32_t cl_loop_iteration_limit(const std::string& device_name) {
    // gallivm's LP_MAX_TGSI_LOOP_ITERATIONS, one counter per invocation.
    return device_name.rfind("llvmpipe", 0) == 0 ? 65535u : 0u;
}

std::vector<DeviceInfo> cl_list_devices() {
    cl_uint np = 0;
    cl_int err = clGetPlatformIDs(0, nullptr, &np);
    if (err == -1001 || np == 0)
        throw InputError("no OpenCL platform found (is an ICD such as pocl-opencl-icd installed?)");
    CL_CHECK(err);
    std::vector<cl_platform_id> platforms(np);
    CL_CHECK(clGetPlatformIDs(np, platforms.data(), nullptr));
    std::vector<DeviceInfo> out;
    for (cl_platform_id p : platforms) {
        cl_uint nd = 0;
        if (clGetDeviceIDs(p, CL_DEVICE_TYPE_ALL, 0, nullptr, &nd) != CL_SUCCESS) continue;
        std::vector<cl_device_id> devs(nd);
        CL_CHECK(clGetDeviceIDs(p, CL_DEVICE_TYPE_ALL, nd, devs.data(), nullptr));
        std::size_t pn = 0;
        CL_CHECK(clGetPlatformInfo(p, CL_PLATFORM_NAME, 0, nullptr, &pn));
        std::string pname(pn, '\0');
        CL_CHECK(clGetPlatformInfo(p, CL_PLATFORM_NAME, pn, pname.data(), nullptr));
        while (!pname.empty() && pname.back() == '\0')
            pname.pop_back();
        for (cl_device_id d : devs) {
            DeviceInfo info;
            info.platform = p;
            info.id = d;
            info.platform_name = pname;
            info.name = device_string(d, CL_DEVICE_NAME);
            info.version = device_string(d, CL_DEVICE_VERSION);
            info.c_version = device_string(d, CL_DEVICE_OPENCL_C_VERSION);
            info.global_mem_bytes = device_value<cl_ulong>(d, CL_DEVICE_GLOBAL_MEM_SIZE);
            info.max_alloc_bytes = device_value<cl_ulong>(d, CL_DEVICE_MAX_MEM_ALLOC_SIZE);
            info.local_mem_bytes = device_value<cl_ulong>(d, CL_DEVICE_LOCAL_MEM_SIZE);
            info.compute_units = device_value<cl_uint>(d, CL_DEVICE_MAX_COMPUTE_UNITS);
            info.max_work_group = device_value<std::size_t>(d, CL_DEVICE_MAX_WORK_GROUP_SIZE);
            info.cpu = device_value<cl_device_type>(d, CL_DEVICE_TYPE) & CL_DEVICE_TYPE_CPU;
            info.loop_iteration_limit = cl_loop_iteration_limit(info.name);
            std::string ext = device_string(d, CL_DEVICE_EXTENSIONS);
            info.int64_atomics = ext.find("cl_khr_int64_base_atomics") != std::string::npos;
            out.push_back(info);
        }
    }
    if (out.empty()) throw InputError("no OpenCL device found on any platform");
    return out;
}

ClContext::ClContext(int device_index) {
    std::vector<DeviceInfo> devices = cl_list_devices();
    if (device_index < 0 || device_index >= static_cast<int>(devices.size()))
        throw UsageError("--device: index " + std::to_string(device_index) +
                         " out of range; `smallmlt devices` lists " +
                         std::to_string(devices.size()) + " device(s)");
    info_ = devices[device_index];
    cl_int err = CL_SUCCESS;
    ctx_ = clCreateContext(nullptr, 1, &info_.id, nullptr, nullptr, &err);
    CL_CHECK(err);
    queue_ = clCreateCommandQueue(ctx_, info_.id, 0, &err);
    CL_CHECK(err);
}

ClContext::~ClContext() {
    if (queue_) clReleaseCommandQueue(queue_);
    if (ctx_) clReleaseContext(ctx_);
}

std::string cl_name_log_lines(const std::string& log, const std::vector<SourceStart>& starts) {
    static const std::string kAnon = "<kernel>:";
    std::string out;
    std::size_t pos = 0;
    for (std::size_t at; (at = log.find(kAnon, pos)) != std::string::npos;) {
        std::size_t digits = at + kAnon.size(), end = digits;
        while (end < log.size() && std::isdigit(static_cast<unsigned char>(log[end])))
            ++end;
        out += log.substr(pos, at - pos);
        pos = end;
        if (end == digits || end == log.size() || log[end] != ':') {
            out += log.substr(at, end - at);
            continue;
        }
        int line = std::atoi(log.c_str() + digits);
        const SourceStart* in = nullptr;
        for (const SourceStart& s : starts)
            if (s.first_line <= line) in = &s;
        out += in ? in->file + ":" + std::to_string(line - in->first_line + 1)
                  : "(defines):" + std::to_string(line);
    }
    return out + log.substr(pos);
}

void ClContext::emulate(const DeviceInfo& limited) {
    cl_platform_id platform = info_.platform;
    cl_device_id id = info_.id;
    info_ = limited;
    info_.platform = platform;
    info_.id = id;
}

namespace {

// Makes every 64-bit atomic function (cl_khr_int64_base_atomics and
// _extended_atomics) a compile error naming what is missing; the 32-bit ones
// are the atomic_* functions of OpenCL 1.1.
std::string forbid_int64_atomics() {
    std::string d;
    for (const char* f :
         {"atom_add", "atom_sub", "atom_xchg", "atom_inc", "atom_dec", "atom_cmpxchg", "atom_min",
          "atom_max", "atom_and", "atom_or", "atom_xor"})
        d += std::string("#undef ") + f + "\n#define " + f + "(...) " + f +
             "_needs_cl_khr_int64_base_atomics_which_this_device_lacks\n";
    return d;
}

} // namespace

cl_program ClContext::build(const std::vector<std::string>& files,
                            const std::string& defines) const {
    std::string src = info_.int64_atomics ? defines : forbid_int64_atomics() + defines;
    std::vector<SourceStart> starts;
    for (const std::string& f : files) {
        src += "#line 1 \"" + f + "\"\n";
        starts.push_back({f, int(std::count(src.begin(), src.end(), '\n')) + 1});
        src += std::string(kernel_source(f)) + "\n";
    }
    const char* text = src.c_str();
    cl_int err = CL_SUCCESS;
    cl_program prog = clCreateProgramWithSource(ctx_, 1, &text, nullptr, &err);
    CL_CHECK(err);
    err = clBuildProgram(prog, 1, &info_.id, "-cl-std=CL1.2", nullptr, nullptr);
    // The compiler (LLVM, as PoCL runs it) deletes its temporary files on
    // SIGINT and SIGTERM, so a build under way at the first signal fails:
    // it is built again, and the render stops where signals are answered.
    if (err == CL_BUILD_PROGRAM_FAILURE && interrupt_requested())
        err = clBuildProgram(prog, 1, &info_.id, "-cl-std=CL1.2", nullptr, nullptr);
    if (err != CL_SUCCESS) {
        std::size_t n = 0;
        clGetProgramBuildInfo(prog, info_.id, CL_PROGRAM_BUILD_LOG, 0, nullptr, &n);
        std::string log(n, '\0');
        clGetProgramBuildInfo(prog, info_.id, CL_PROGRAM_BUILD_LOG, n, log.data(), nullptr);
        clReleaseProgram(prog);
        throw InputError(std::string("kernel build failed (") + cl_error_name(err) + ") on " +
                         info_.name + ":\n" + cl_name_log_lines(log, starts));
    }
    return prog;
}

void ClContext::count_alloc(std::int64_t bytes) const {
    live_bytes_ = std::uint64_t(std::int64_t(live_bytes_) + bytes);
    if (live_bytes_ > peak_bytes_) peak_bytes_ = live_bytes_;
}

ClBuffer::ClBuffer(const ClContext& cl, cl_mem_flags flags, std::size_t bytes, const void* host)
    : cl_(&cl), bytes_(bytes) {
    cl_int err = CL_SUCCESS;
    std::size_t n = device_alloc_bytes(bytes);
    mem_ = clCreateBuffer(cl.context(), flags | (host && bytes ? CL_MEM_COPY_HOST_PTR : 0), n,
                          bytes ? const_cast<void*>(host) : nullptr, &err);
    if (err != CL_SUCCESS)
        throw InputError("clCreateBuffer of " + std::to_string(n) +
                         " bytes failed: " + cl_error_name(err));
    cl.count_alloc(std::int64_t(n));
}

ClBuffer::~ClBuffer() {
    if (!mem_) return;
    clReleaseMemObject(mem_);
    cl_->count_alloc(-std::int64_t(device_alloc_bytes(bytes_)));
}

ClBuffer::ClBuffer(ClBuffer&& o) noexcept : cl_(o.cl_), mem_(o.mem_), bytes_(o.bytes_) {
    o.mem_ = nullptr;
}

ClBuffer& ClBuffer::operator=(ClBuffer&& o) noexcept {
    if (this != &o) {
        this->~ClBuffer();
        cl_ = o.cl_;
        mem_ = o.mem_;
        bytes_ = o.bytes_;
        o.mem_ = nullptr;
    }
    return *this;
}

void ClBuffer::read(const ClContext& cl, void* dst) const {
    if (bytes_)
        CL_CHECK(
            clEnqueueReadBuffer(cl.queue(), mem_, CL_TRUE, 0, bytes_, dst, 0, nullptr, nullptr));
}

void ClBuffer::write(const ClContext& cl, const void* src) const {
    if (bytes_)
        CL_CHECK(
            clEnqueueWriteBuffer(cl.queue(), mem_, CL_TRUE, 0, bytes_, src, 0, nullptr, nullptr));
}

void ClBuffer::fill_zero(const ClContext& cl) const {
    if (!bytes_) return;
    const cl_uint zero = 0;
    CL_CHECK(
        clEnqueueFillBuffer(cl.queue(), mem_, &zero, sizeof(zero), 0, bytes_, 0, nullptr, nullptr));
}

ClKernel::ClKernel(cl_program program, const char* name) : name_(name) {
    cl_int err = CL_SUCCESS;
    k_ = clCreateKernel(program, name, &err);
    if (err != CL_SUCCESS)
        throw InputError(std::string("clCreateKernel(") + name + ") failed: " + cl_error_name(err));
    CL_CHECK(clGetKernelInfo(k_, CL_KERNEL_NUM_ARGS, sizeof(num_args_), &num_args_, nullptr));
}

ClKernel::~ClKernel() {
    if (k_) clReleaseKernel(k_);
}

void ClKernel::check_arg_count(cl_uint set) const {
    if (set != num_args_)
        throw std::logic_error("kernel " + name_ + " takes " + std::to_string(num_args_) +
                               " arguments, " + std::to_string(set) + " were set");
}

void ClKernel::set_arg(cl_uint i, const ClBuffer& b) {
    cl_mem m = b.get();
    set_raw(i, sizeof(cl_mem), &m);
}

void ClKernel::set_raw(cl_uint i, std::size_t bytes, const void* v) {
    cl_int err = clSetKernelArg(k_, i, bytes, v);
    if (err != CL_SUCCESS)
        throw InputError("clSetKernelArg(" + name_ + ", arg " + std::to_string(i) +
                         ") failed: " + cl_error_name(err));
}

void ClKernel::enqueue(const ClContext& cl, std::size_t items, std::size_t local) const {
    if (items == 0) return;
    std::size_t global = (items + local - 1) / local * local;
    cl_int err =
        clEnqueueNDRangeKernel(cl.queue(), k_, 1, nullptr, &global, &local, 0, nullptr, nullptr);
    if (err != CL_SUCCESS)
        throw InputError("kernel " + name_ + " over " + std::to_string(global) +
                         " work-items (work-group " + std::to_string(local) +
                         ") failed: " + cl_error_name(err));
}

void ClKernel::run(const ClContext& cl, std::size_t items, std::size_t local) const {
    enqueue(cl, items, local);
    cl.finish("kernel " + name_ + " over " + std::to_string(items) + " work-items");
}

void ClContext::finish(const std::string& what) const {
    cl_int err = clFinish(queue_);
    if (err != CL_SUCCESS) throw InputError(what + " failed: " + cl_error_name(err));
}

ClProgram::~ClProgram() {
    if (p) clReleaseProgram(p);
}

} // namespace smallmlt
