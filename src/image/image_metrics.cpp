#include "image/image_metrics.hpp"

#include "base/error.hpp"

namespace smallmlt {

void require_same_size(const Image& img, const Image& ref, const std::string& what) {
    if (img.width != ref.width || img.height != ref.height)
        throw InputError(what + ": image is " + std::to_string(img.width) + "x" +
                         std::to_string(img.height) + ", reference " + std::to_string(ref.width) +
                         "x" + std::to_string(ref.height));
}

double image_mse(const Image& img, const Image& ref) {
    double s = 0;
    for (std::size_t i = 0; i < img.rgb.size(); ++i) {
        double d = double(img.rgb[i]) - ref.rgb[i];
        s += d * d;
    }
    return img.rgb.empty() ? 0.0 : s / double(img.rgb.size());
}

double image_rel_mse(const Image& img, const Image& ref) {
    double s = 0;
    for (std::size_t i = 0; i < img.rgb.size(); ++i) {
        double d = double(img.rgb[i]) - ref.rgb[i];
        s += d * d / (double(ref.rgb[i]) * ref.rgb[i] + kRelMseEpsilon);
    }
    return img.rgb.empty() ? 0.0 : s / double(img.rgb.size());
}

} // namespace smallmlt
