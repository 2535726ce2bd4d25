#include "device/scan.hpp"

namespace smallmlt {

std::size_t scan_work_group(const DeviceInfo& dev) {
    std::size_t wg = 256;
    while (wg > 1 && wg > dev.max_work_group)
        wg /= 2;
    return wg;
}

std::string scan_defines(const DeviceInfo& dev) {
    return "#define SCAN_WG " + std::to_string(scan_work_group(dev)) + "u\n";
}

std::vector<std::size_t> scan_levels(std::size_t n, std::size_t wg) {
    std::vector<std::size_t> levels;
    for (std::size_t per_block = 2 * wg; n > per_block;) {
        n = (n + per_block - 1) / per_block;
        levels.push_back(n);
    }
    return levels;
}

std::uint64_t scan_bytes(std::size_t n, std::size_t wg, std::size_t element_bytes) {
    std::uint64_t b = device_alloc_bytes(element_bytes);
    for (std::size_t count : scan_levels(n, wg))
        b += 2 * device_alloc_bytes(count * element_bytes);
    return b;
}

DeviceScan::DeviceScan(const ClContext& cl, cl_program program, std::size_t max_n,
                       std::size_t element_bytes)
    : cl_(cl), wg_(scan_work_group(cl.device())), blocks_(program, "scan_blocks"),
      add_(program, "scan_add") {
    for (std::size_t n : scan_levels(max_n, wg_)) {
        sums_.emplace_back(cl, CL_MEM_READ_WRITE, n * element_bytes);
        prefix_.emplace_back(cl, CL_MEM_READ_WRITE, n * element_bytes);
    }
    // The last level is a single block whose total is written but not used.
    sums_.emplace_back(cl, CL_MEM_READ_WRITE, element_bytes);
}

void DeviceScan::run(const ClBuffer& in, const ClBuffer& out, std::size_t n) {
    if (n > 0) run_level(in, out, n, 0);
}

void DeviceScan::run_level(const ClBuffer& in, const ClBuffer& out, std::size_t n,
                           std::size_t level) {
    std::size_t per_block = 2 * wg_;
    std::size_t blocks = (n + per_block - 1) / per_block;
    const ClBuffer& sums = blocks > 1 ? sums_[level] : sums_.back();
    blocks_.set_args(in, out, sums, cl_uint(n));
    blocks_.enqueue(cl_, blocks * wg_, wg_);
    if (blocks == 1) return;
    run_level(sums, prefix_[level], blocks, level + 1);
    add_.set_args(out, prefix_[level], cl_uint(n));
    add_.enqueue(cl_, blocks * wg_, wg_);
}

} // namespace smallmlt
