// Image files: PFM and EXR hold linear radiance exactly; the format follows
// the extension; writes leave no temporary file behind.
#include "base/error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <dirent.h>

using namespace smallmlt;

namespace {

Image ramp() {
    Image img(5, 3);
    for (std::size_t i = 0; i < img.rgb.size(); ++i)
        img.rgb[i] = 0.1f * float(i) + 1e-3f;
    return img;
}

std::size_t files_in(const std::string& dir) {
    std::size_t n = 0;
    DIR* d = opendir(dir.c_str());
    while (dirent* e = readdir(d)) {
        std::string name = e->d_name;
        n += name != "." && name != "..";
    }
    closedir(d);
    return n;
}

} // namespace

TEST(ImageIo, PfmRoundTripIsExact) {
    std::string dir = test::scratch_dir("pfm");
    write_image(ramp(), dir + "/a.pfm");
    Image back = read_pfm(dir + "/a.pfm");
    EXPECT_EQ(back.width, 5);
    EXPECT_EQ(back.height, 3);
    EXPECT_EQ(back.rgb, ramp().rgb);
    EXPECT_EQ(files_in(dir), 1u);
}

TEST(ImageIo, ExrRoundTripIsExact) {
    std::string dir = test::scratch_dir("exr");
    write_image(ramp(), dir + "/a.exr");
    Image back = read_exr(dir + "/a.exr");
    EXPECT_EQ(back.rgb, ramp().rgb);
}

TEST(ImageIo, FormatFromExtension) {
    EXPECT_EQ(image_format_of("x/y.PNG"), ImageFormat::Png);
    EXPECT_EQ(image_format_of("y.exr"), ImageFormat::Exr);
    EXPECT_THROW(image_format_of("y.jpg"), UsageError);
    EXPECT_THROW(image_format_of("dir.png/y"), UsageError);
}

TEST(ImageIo, UnwritableTargetThrowsAndLeavesNothing) {
    std::string dir = test::scratch_dir("unwritable");
    EXPECT_THROW(write_image(ramp(), dir + "/missing/a.png"), InputError);
    EXPECT_EQ(files_in(dir), 0u);
}
