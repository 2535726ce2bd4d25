// Profiles of real small OpenCL devices, from public clinfo reports
// (doc/devices.md gives each source): `--profile NAME` makes the device at
// hand count as that one (never as more than itself), so a render is sized,
// split and compiled as it would be there.
#pragma once
#include "device/ocl.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace smallmlt {

struct DeviceProfile {
    std::string name;   // --profile NAME
    std::string device; // as its clinfo report names it
    std::uint64_t global_mem_bytes, max_alloc_bytes, local_mem_bytes;
    std::uint32_t compute_units;
    std::size_t max_work_group;
    bool int64_atomics; // cl_khr_int64_base_atomics in its extensions
    std::string source; // the report the figures come from
};

const std::vector<DeviceProfile>& device_profiles();

// Throws UsageError naming --profile and the known names.
const DeviceProfile& find_device_profile(const std::string& name);

// `real` as the profile: its memory, largest allocation and local memory
// (each never more than real's), 64-bit atomics only where both have them,
// and the profile's compute units and work-group size, which size the
// thread count; the name says what it emulates.
DeviceInfo emulate_profile(const DeviceInfo& real, const DeviceProfile& p);

// `real` limited to `bytes` of memory with a largest allocation of a quarter
// of that (--device-mem), never more than it has.
DeviceInfo emulate_memory(const DeviceInfo& real, std::uint64_t bytes);

} // namespace smallmlt
