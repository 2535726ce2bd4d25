// `smallmlt compare`: the error of one image against a reference.
#include "app/commands.hpp"

#include "image/image.hpp"
#include "image/image_metrics.hpp"

#include <cstdio>

namespace smallmlt {

int run_compare(const std::string& image, const std::string& reference) {
    Image img = read_image(image), ref = read_image(reference);
    require_same_size(img, ref, image);
    std::printf("mse %.6g rel_mse %.6g mean %.6g reference_mean %.6g\n", image_mse(img, ref),
                image_rel_mse(img, ref), img.mean_luminance(), ref.mean_luminance());
    return 0;
}

} // namespace smallmlt
