// OpenCL trouble that can be provoked on any device: a kernel that does not
// build reports its log with the real file names, a launch the device
// refuses names the kernel and its sizes, and a device without the 64-bit
// atomics MLT needs is refused with a way out. (No platform at all is
// checked from the command line: test/cli_test.sh, no_platform.)
#include "base/error.hpp"
#include "render/mlt.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <functional>

using namespace smallmlt;

namespace {

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(OpenCl, BuildFailurePrintsTheLogWithFileAndLine) {
    // A define that breaks the shared header: the log must point into it.
    std::string msg = error_of([] {
        test::cl().build({"cl/shared_types.h", "cl/rng.cl"}, "#define u32 @\n");
    });
    EXPECT_NE(msg.find("kernel build failed (CL_BUILD_PROGRAM_FAILURE)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("cl/shared_types.h:"), std::string::npos) << msg;
}

// Compilers that ignore #line (NVIDIA's names every line "<kernel>:N") get
// their line numbers mapped back to the embedded file and its own line.
TEST(OpenCl, AnonymousLogLinesNameTheEmbeddedFile) {
    std::vector<SourceStart> starts = {{"cl/shared_types.h", 4}, {"cl/rng.cl", 120}};
    EXPECT_EQ(cl_name_log_lines("<kernel>:83:5: error: x\n<kernel>:121:2: note\n<kernel>:2:1: w "
                                "<kernel>:zz <kernel>:7",
                                starts),
              "cl/shared_types.h:80:5: error: x\ncl/rng.cl:2:2: note\n(defines):2:1: w "
              "<kernel>:zz <kernel>:7");
}

TEST(OpenCl, RefusedLaunchNamesKernelAndSizes) {
    ClProgram program(test::cl().build(
        {"cl/shared_types.h", "cl/geometry.cl", "cl/bvh.cl", "cl/kernels_probe.cl"}, ""));
    ClKernel k(program.p, "probe_layout");
    std::size_t too_big = test::cl().device().max_work_group * 2;
    std::string msg = error_of([&] { k.enqueue(test::cl(), too_big, too_big); });
    EXPECT_NE(msg.find("kernel probe_layout over " + std::to_string(too_big) + " work-items"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("CL_INVALID_WORK_GROUP_SIZE"), std::string::npos) << msg;
}

// MLT needs 64-bit atomics only for the 64-bit reference film.
TEST(OpenCl, OnlyThe64BitFilmNeedsInt64Atomics) {
    DeviceInfo d = test::cl().device();
    MltOptions film64;
    film64.film_atomics64 = true;
    EXPECT_EQ(error_of([&] { mlt_require_device(d, film64); }), "");
    d.int64_atomics = false;
    EXPECT_EQ(error_of([&] { mlt_require_device(d, MltOptions()); }), "");
    std::string msg = error_of([&] { mlt_require_device(d, film64); });
    EXPECT_NE(msg.find("lacks cl_khr_int64_base_atomics"), std::string::npos) << msg;
    EXPECT_NE(msg.find("--film-atomics 64"), std::string::npos) << msg;
}
