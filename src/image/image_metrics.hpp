// Error of an image against a reference, on linear HDR values over all
// pixels and channels (but for image_mse_excluding's masked pixels). The
// caller checks that image and reference have the same size.
#pragma once
#include "image/image.hpp"

#include <string>

namespace smallmlt {

// Mean squared error.
double image_mse(const Image& img, const Image& ref);

// Relative MSE: mean of (img - ref)^2 / (ref^2 + kRelMseEpsilon), which
// weighs dark and bright regions alike.
constexpr double kRelMseEpsilon = 1e-2;
double image_rel_mse(const Image& img, const Image& ref);

// Block MSE: the film cut into non-overlapping `block` x `block` pixel
// blocks from the top left (those at the right and bottom edges may be
// smaller), each channel averaged over each block in both images; the mean
// over blocks and channels of the squared difference of those means. Blind
// to noise that averages out within a block. Throws std::invalid_argument
// unless block >= 1.
constexpr int kErrorBlock = 8;      // block8_mse
constexpr int kErrorBlockWide = 32; // block32_mse: the scale of MLT's blotches
double image_block_mse(const Image& img, const Image& ref, int block);

// MSE over the pixels where `mask` has zero luminance, e.g. all but the
// directly visible lights when the mask is a depth-0 render; 0 if the mask
// leaves no pixel. Throws InputError, naming `mask_name`, unless the mask
// has the image's size.
double image_mse_excluding(const Image& img, const Image& ref, const Image& mask,
                           const std::string& mask_name = "mask");

// Throws InputError unless the two have the same size.
void require_same_size(const Image& img, const Image& ref, const std::string& what);

} // namespace smallmlt
