#include "scan.hpp"

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

DeviceScan::DeviceScan(const ClContext& cl, cl_program program, std::size_t max_n,
                       std::size_t element_bytes)
    : cl_(cl), wg_(scan_work_group(cl.device())), blocks_(program, "scan_blocks"),
      add_(program, "scan_add") {
    std::size_t per_block = 2 * wg_;
    for (std::size_t n = max_n; n > per_block;) {
        n = (n + per_block - 1) / per_block;
        sums_.emplace_back(cl, CL_MEM_READ_WRITE, n * element_bytes);
        prefix_.emplace_back(cl, CL_MEM_READ_WRITE, n * element_bytes);
    }
    // The last level is a single block whose total is written but not used.
    sums_.emplace_back(cl, CL_MEM_READ_WRITE, element_bytes);
}

std::size_t DeviceScan::bytes() const {
    std::size_t b = 0;
    for (const ClBuffer& x : sums_)
        b += x.bytes();
    for (const ClBuffer& x : prefix_)
        b += x.bytes();
    return b;
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
