// `smallmlt compare`: the error of one image against a reference, on one
// line of name-value pairs; mse_unlit comes last, with --mask only.
#include "app/commands.hpp"

#include "image/image.hpp"
#include "image/image_metrics.hpp"

#include <cstdio>

namespace smallmlt {

int run_compare(const std::string& image, const std::string& reference, const std::string& mask) {
    Image img = read_image(image), ref = read_image(reference);
    require_same_size(img, ref, image);
    std::string unlit;
    if (!mask.empty()) {
        char v[32];
        std::snprintf(v, sizeof v, " mse_unlit %.6g",
                      image_mse_excluding(img, ref, read_image(mask), mask));
        unlit = v;
    }
    std::printf("mse %.6g rel_mse %.6g mean %.6g reference_mean %.6g block8_mse %.6g "
                "block32_mse %.6g%s\n",
                image_mse(img, ref), image_rel_mse(img, ref), img.mean_luminance(),
                ref.mean_luminance(), image_block_mse(img, ref, kErrorBlock),
                image_block_mse(img, ref, kErrorBlockWide), unlit.c_str());
    return 0;
}

} // namespace smallmlt
