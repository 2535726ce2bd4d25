// Image files: PFM and EXR hold linear radiance exactly; the format follows
// the extension; writes leave no temporary file behind. Error metrics
// (image_metrics.hpp) on small images computed by hand.
#include "base/error.hpp"
#include "image/image_metrics.hpp"
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

// Channel c of pixel (x, y).
float& at(Image& img, int x, int y, int c) {
    return img.rgb[(std::size_t(y) * img.width + x) * 3 + c];
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

TEST(ImageMetrics, BlockMseAveragesPartialEdgeBlocksOverTheirOwnPixels) {
    // Red of a 3x3 image against black, blocks of 2: full block {1, 3, 2, 2}
    // (mean 2), right {5, 7} (6), bottom {4, 0} (2), corner {9}; green and
    // blue agree. (4 + 36 + 4 + 81) / (4 blocks x 3 channels).
    Image img(3, 3), ref(3, 3);
    const float red[3][3] = {{1, 3, 5}, {2, 2, 7}, {4, 0, 9}};
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x)
            at(img, x, y, 0) = red[y][x];
    EXPECT_DOUBLE_EQ(image_block_mse(img, ref, 2), 125.0 / 12.0);
    // One block holds the whole image: its mean 33/9 in red.
    EXPECT_DOUBLE_EQ(image_block_mse(img, ref, 8), (33.0 / 9) * (33.0 / 9) / 3);
    // Blocks of one pixel: the MSE.
    EXPECT_DOUBLE_EQ(image_block_mse(img, ref, 1), image_mse(img, ref));
    EXPECT_THROW(image_block_mse(img, ref, 0), std::invalid_argument);
}

TEST(ImageMetrics, BlockMseIgnoresNoiseThatAveragesOutWithinABlock) {
    // A checkerboard of +-0.25 about the reference: each 8x8 block holds as
    // many + as -, so every block mean agrees while every pixel is off.
    Image img(16, 16), ref(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) {
                at(ref, x, y, c) = 0.5f;
                at(img, x, y, c) = (x + y + c) % 2 ? 0.75f : 0.25f;
            }
    EXPECT_DOUBLE_EQ(image_mse(img, ref), 0.0625);
    EXPECT_DOUBLE_EQ(image_block_mse(img, ref, kErrorBlock), 0.0);
    // An offset of the whole image is in every block mean.
    for (float& v : img.rgb)
        v += 0.125f;
    EXPECT_DOUBLE_EQ(image_block_mse(img, ref, kErrorBlock), 0.125 * 0.125);
    // 15 = 2 x 7 + 1 columns, blocks of 2: noise across rows averages out in
    // the 1x2 edge blocks too, noise across columns does not.
    Image odd(15, 16), odd_ref(15, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 15; ++x)
            at(odd, x, y, 0) = y % 2 ? 1.0f : -1.0f;
    EXPECT_DOUBLE_EQ(image_block_mse(odd, odd_ref, 2), 0.0);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 15; ++x)
            at(odd, x, y, 0) = x % 2 ? 1.0f : -1.0f;
    // 8 rows x 8 columns of blocks; the last column's blocks hold x = 14
    // alone (-1): 8 blocks of squared mean 1, over 64 blocks x 3 channels.
    EXPECT_DOUBLE_EQ(image_block_mse(odd, odd_ref, 2), 8.0 / (64 * 3));
}

TEST(ImageMetrics, MseExcludingLeavesOutThePixelsTheMaskLights) {
    // Pixels (1, 1, 1), (10, 10, 10), (2, 0, 0), (0, 0, 3) against black; the
    // mask lights the second (in blue alone: luminance 0.0722).
    Image img(2, 2), ref(2, 2), mask(2, 2);
    img.rgb = {1, 1, 1, 10, 10, 10, 2, 0, 0, 0, 0, 3};
    at(mask, 1, 0, 2) = 1.0f;
    EXPECT_DOUBLE_EQ(image_mse_excluding(img, ref, mask), (3.0 + 4 + 9) / 9);
    // A black mask leaves out nothing; one that lights all leaves nothing.
    EXPECT_DOUBLE_EQ(image_mse_excluding(img, ref, Image(2, 2)), image_mse(img, ref));
    Image all(2, 2);
    for (float& v : all.rgb)
        v = 0.5f;
    EXPECT_DOUBLE_EQ(image_mse_excluding(img, ref, all), 0.0);
}

TEST(ImageMetrics, SizeMismatchesThrowInputErrorsNamingTheFile) {
    Image img(2, 2), ref(2, 2);
    EXPECT_EQ(test::input_error_of([&] { image_mse_excluding(img, ref, Image(3, 2), "m.pfm"); }),
              "m.pfm: mask is 3x2, image 2x2");
    EXPECT_EQ(test::input_error_of([&] { image_mse_excluding(img, ref, Image(2, 1)); }),
              "mask: mask is 2x1, image 2x2");
    EXPECT_EQ(test::input_error_of([&] { require_same_size(img, Image(2, 3), "a.pfm"); }),
              "a.pfm: image is 2x2, reference 2x3");
    EXPECT_EQ(test::input_error_of([&] { require_same_size(img, ref, "a.pfm"); }), "");
}
