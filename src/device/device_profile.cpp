#include "device/device_profile.hpp"

#include "base/error.hpp"

#include <algorithm>

namespace smallmlt {

const std::vector<DeviceProfile>& device_profiles() {
    static const std::vector<DeviceProfile> profiles = {
        {"mali-g610", "Mali-G610 (Mali-LODX r0p0, RK3588)", 33327280128ull, 33327280128ull, 32768,
         4, 1024, true,
         "github.com/clouetb/clouetb.github.io, "
         "posts/running-llama3-on-the-gpu-of-a-rk1-turing-pi.rst"},
        {"adreno-650", "QUALCOMM Adreno(TM) 650", 3992293376ull, 998073344ull, 32768, 3, 1024,
         false, "github.com/xmrig/xmrig/issues/2383"},
        {"apple-m1", "Apple M1 (macOS 13.5.2)", 11453251584ull, 2147483648ull, 32768, 8, 256, false,
         "github.com/pynufft/pynufft, doc/source/installation/Macbook.rst"},
        {"videocore-iv", "VideoCore IV GPU (VC4CL 0.4, Raspberry Pi 3B+)", 268435456ull,
         268435456ull, 268435456ull, 1, 12, false,
         "github.com/linzhanyu/linzhanyu.github.io, _posts/2019-09-23-OpenCL-rspi3.md"},
    };
    return profiles;
}

const DeviceProfile& find_device_profile(const std::string& name) {
    std::string known;
    for (const DeviceProfile& p : device_profiles()) {
        if (p.name == name) return p;
        known += (known.empty() ? "" : ", ") + p.name;
    }
    throw UsageError("--profile: '" + name + "' is not a device profile (" + known + ")");
}

DeviceInfo emulate_profile(const DeviceInfo& real, const DeviceProfile& p) {
    DeviceInfo d = real;
    d.name = p.name + " (emulated on " + real.name + ")";
    d.global_mem_bytes = std::min(real.global_mem_bytes, p.global_mem_bytes);
    d.max_alloc_bytes = std::min(real.max_alloc_bytes, p.max_alloc_bytes);
    d.local_mem_bytes = std::min(real.local_mem_bytes, p.local_mem_bytes);
    d.compute_units = p.compute_units; // these size the thread count only
    d.max_work_group = p.max_work_group;
    d.cpu = false; // every profile is a GPU
    d.int64_atomics = real.int64_atomics && p.int64_atomics;
    d.emulated = true;
    return d;
}

DeviceInfo emulate_memory(const DeviceInfo& real, std::uint64_t bytes) {
    DeviceInfo d = real;
    d.global_mem_bytes = std::min(bytes, real.global_mem_bytes);
    d.max_alloc_bytes = std::min(real.max_alloc_bytes, d.global_mem_bytes / 4);
    d.emulated = true;
    return d;
}

} // namespace smallmlt
