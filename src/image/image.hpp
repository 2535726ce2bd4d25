// Linear-radiance RGB images and their files: PNG (tone-mapped: clamped,
// sRGB-encoded, 8 bits), PFM and EXR (linear float). Files are written
// atomically: to a temporary name beside the target, then renamed.
#pragma once
#include "base/color.hpp"

#include <string>
#include <vector>

namespace smallmlt {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb; // row-major from the top row, 3 floats per pixel

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * h * 3, 0.0f) {}
    double luminance(std::size_t pixel) const {
        return rgb_luminance(rgb[3 * pixel], rgb[3 * pixel + 1], rgb[3 * pixel + 2]);
    }
    double mean_luminance() const;
};

enum class ImageFormat { Png, Pfm, Exr };

// Format from the file name's extension; throws UsageError for others,
// naming `flag` (if not empty) and the file.
ImageFormat image_format_of(const std::string& path, const std::string& flag = "--out");

void write_image(const Image& img, const std::string& path);

// Reads a PFM written by write_image (or any colour "PF" file).
Image read_pfm(const std::string& path);

// Reads an RGB EXR file.
Image read_exr(const std::string& path);

// Reads a PFM or EXR file, by extension.
Image read_image(const std::string& path);

} // namespace smallmlt
