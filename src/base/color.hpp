// Colour on the host: luminance of linear RGB.
#pragma once

namespace smallmlt {

// Luminance of linear RGB (Rec. 709 weights), as cl/path/path.cl's path_luminance.
inline double rgb_luminance(double r, double g, double b) {
    return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

} // namespace smallmlt
