// Inclusive prefix sums on the device with the kernels of cl/core/scan.cl:
// blocks of 2 * work-group elements, then the block totals, recursively.
#pragma once
#include "device/ocl.hpp"

#include <vector>

namespace smallmlt {

// Work-group size of the scan on this device (a power of two, at most 256);
// the program must be built with `#define SCAN_WG` of this value.
std::size_t scan_work_group(const DeviceInfo& dev);
std::string scan_defines(const DeviceInfo& dev);

// Elements of the block totals at each level of a scan of n elements; the
// scan holds two buffers of that many per level and one more element.
std::vector<std::size_t> scan_levels(std::size_t n, std::size_t wg);
// Device bytes of those buffers, as DeviceScan allocates them.
std::uint64_t scan_bytes(std::size_t n, std::size_t wg, std::size_t element_bytes);

class DeviceScan {
  public:
    // Scans of up to max_n elements of `element_bytes` each with the
    // scan_blocks and scan_add kernels of `program`.
    DeviceScan(const ClContext& cl, cl_program program, std::size_t max_n,
               std::size_t element_bytes);
    // out[i] = in[0] + ... + in[i] for i < n (queued; not waited for).
    void run(const ClBuffer& in, const ClBuffer& out, std::size_t n);

  private:
    void run_level(const ClBuffer& in, const ClBuffer& out, std::size_t n, std::size_t level);

    const ClContext& cl_;
    std::size_t wg_;
    ClKernel blocks_, add_;
    std::vector<ClBuffer> sums_, prefix_; // per level: block totals and their scan
};

} // namespace smallmlt
