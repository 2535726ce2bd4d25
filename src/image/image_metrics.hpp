// Error of an image against a reference, on linear HDR values over all
// pixels and channels.
#pragma once
#include "image/image.hpp"

namespace smallmlt {

// Mean squared error.
double image_mse(const Image& img, const Image& ref);

// Relative MSE: mean of (img - ref)^2 / (ref^2 + kRelMseEpsilon), which
// weighs dark and bright regions alike.
constexpr double kRelMseEpsilon = 1e-2;
double image_rel_mse(const Image& img, const Image& ref);

// Throws InputError unless the two have the same size.
void require_same_size(const Image& img, const Image& ref, const std::string& what);

} // namespace smallmlt
