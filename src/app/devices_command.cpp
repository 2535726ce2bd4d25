// `smallmlt devices`: every OpenCL device, with what a render's budget uses.
#include "app/commands.hpp"

#include "device/ocl.hpp"

#include <cstdio>
#include <vector>

namespace smallmlt {

int run_devices() {
    std::vector<DeviceInfo> devs = cl_list_devices();
    for (std::size_t i = 0; i < devs.size(); ++i) {
        const DeviceInfo& d = devs[i];
        std::printf("%zu: %s (%s)\n   %s, %s\n   %u compute units, global memory %.1f MiB, "
                    "max allocation %.1f MiB, local memory %.1f KiB%s\n",
                    i, d.name.c_str(), d.platform_name.c_str(), d.version.c_str(),
                    d.c_version.c_str(), d.compute_units, d.global_mem_bytes / 1048576.0,
                    d.max_alloc_bytes / 1048576.0, d.local_mem_bytes / 1024.0,
                    d.int64_atomics ? ", 64-bit atomics" : "");
    }
    return 0;
}

} // namespace smallmlt
