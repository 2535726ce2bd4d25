#include "image/image_metrics.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace smallmlt {

namespace {

std::string size_text(const Image& img) {
    return std::to_string(img.width) + "x" + std::to_string(img.height);
}

} // namespace

void require_same_size(const Image& img, const Image& ref, const std::string& what) {
    if (img.width != ref.width || img.height != ref.height)
        throw InputError(what + ": image is " + size_text(img) + ", reference " + size_text(ref));
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

double image_block_mse(const Image& img, const Image& ref, int block) {
    if (block < 1) throw std::invalid_argument("image_block_mse: block must be at least 1");
    // The difference of two block means is the block mean of the difference.
    int bw = (img.width + block - 1) / block, bh = (img.height + block - 1) / block;
    double s = 0;
    std::vector<double> sum(std::size_t(bw) * 3);
    for (int by = 0; by < bh; ++by) {
        std::fill(sum.begin(), sum.end(), 0.0);
        int y0 = by * block, y1 = std::min(y0 + block, img.height);
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < img.width; ++x)
                for (int c = 0; c < 3; ++c) {
                    std::size_t i = (std::size_t(y) * img.width + x) * 3 + c;
                    sum[std::size_t(x / block) * 3 + c] += double(img.rgb[i]) - ref.rgb[i];
                }
        for (int bx = 0; bx < bw; ++bx) {
            int pixels = (y1 - y0) * (std::min((bx + 1) * block, img.width) - bx * block);
            for (int c = 0; c < 3; ++c) {
                double d = sum[std::size_t(bx) * 3 + c] / pixels;
                s += d * d;
            }
        }
    }
    return bw * bh == 0 ? 0.0 : s / (double(bw) * bh * 3);
}

double image_mse_excluding(const Image& img, const Image& ref, const Image& mask,
                           const std::string& mask_name) {
    if (mask.width != img.width || mask.height != img.height)
        throw InputError(mask_name + ": mask is " + size_text(mask) + ", image " + size_text(img));
    double s = 0;
    std::size_t n = 0;
    for (std::size_t p = 0; p < std::size_t(img.width) * img.height; ++p) {
        if (mask.luminance(p) != 0) continue;
        for (std::size_t i = 3 * p; i < 3 * p + 3; ++i) {
            double d = double(img.rgb[i]) - ref.rgb[i];
            s += d * d;
        }
        n += 3;
    }
    return n == 0 ? 0.0 : s / double(n);
}

} // namespace smallmlt
