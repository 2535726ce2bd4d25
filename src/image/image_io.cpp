// Image files. The only translation unit that includes the stb and tinyexr
// headers (system headers; their code is linked from the Debian libraries).
#include "base/error.hpp"
#include "base/interrupt.hpp"
#include "image/image.hpp"

#include <stb/stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <unistd.h>

namespace smallmlt {

namespace {

std::string lower_ext(const std::string& path) {
    std::size_t dot = path.find_last_of('.');
    std::size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string e = path.substr(dot + 1);
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return e;
}

unsigned char to_srgb8(float v) {
    v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
    float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return static_cast<unsigned char>(std::lround(s * 255.0f));
}

bool write_png(const Image& img, const std::string& path) {
    std::vector<unsigned char> px(img.rgb.size());
    for (std::size_t i = 0; i < px.size(); ++i)
        px[i] = to_srgb8(img.rgb[i]);
    return stbi_write_png(path.c_str(), img.width, img.height, 3, px.data(), img.width * 3) != 0;
}

// PFM stores rows bottom to top; a negative scale means little-endian.
bool write_pfm(const Image& img, const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    out << "PF\n" << img.width << " " << img.height << "\n-1.0\n";
    for (int y = img.height - 1; y >= 0; --y)
        out.write(reinterpret_cast<const char*>(&img.rgb[std::size_t(y) * img.width * 3]),
                  std::streamsize(sizeof(float)) * img.width * 3);
    return bool(out.flush());
}

bool write_exr(const Image& img, const std::string& path) {
    const char* err = nullptr;
    int rc = SaveEXR(img.rgb.data(), img.width, img.height, 3, 0, path.c_str(), &err);
    if (err) FreeEXRErrorMessage(err);
    return rc == TINYEXR_SUCCESS;
}

} // namespace

double Image::mean_luminance() const {
    double sum = 0;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
        sum += rgb_luminance(rgb[i], rgb[i + 1], rgb[i + 2]);
    return rgb.empty() ? 0.0 : sum / double(rgb.size() / 3);
}

ImageFormat image_format_of(const std::string& path, const std::string& flag) {
    std::string e = lower_ext(path);
    if (e == "png") return ImageFormat::Png;
    if (e == "pfm") return ImageFormat::Pfm;
    if (e == "exr") return ImageFormat::Exr;
    throw UsageError((flag.empty() ? "" : flag + " ") + path +
                     ": unknown image format (use .png, .pfm or .exr)");
}

void write_image(const Image& img, const std::string& path) {
    ImageFormat fmt = image_format_of(path);
    // Keep the real extension last: the writers do not care, viewers might.
    std::size_t slash = path.find_last_of('/');
    std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    std::string tmp = dir + ".tmp-" + std::to_string(getpid()) + "-" +
                      path.substr(slash == std::string::npos ? 0 : slash + 1);
    TempFileGuard guard(tmp);
    bool ok = fmt == ImageFormat::Png   ? write_png(img, tmp)
              : fmt == ImageFormat::Pfm ? write_pfm(img, tmp)
                                        : write_exr(img, tmp);
    if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::string why = std::strerror(errno);
        std::remove(tmp.c_str());
        throw InputError(path + ": cannot write image (" + why + ")");
    }
}

Image read_pfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open image");
    std::string magic;
    int w = 0, h = 0;
    float scale = 0;
    if (!(in >> magic >> w >> h >> scale) || magic != "PF" || w <= 0 || h <= 0 || scale >= 0)
        throw InputError(path + ": not a little-endian colour PFM file");
    in.get();
    Image img(w, h);
    for (int y = h - 1; y >= 0; --y)
        in.read(reinterpret_cast<char*>(&img.rgb[std::size_t(y) * w * 3]),
                std::streamsize(sizeof(float)) * w * 3);
    if (!in) throw InputError(path + ": truncated PFM file");
    return img;
}

Image read_exr(const std::string& path) {
    float* data = nullptr;
    int w = 0, h = 0;
    const char* err = nullptr;
    if (LoadEXR(&data, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
        std::string msg = err ? err : "unknown error";
        if (err) FreeEXRErrorMessage(err);
        throw InputError(path + ": cannot read EXR: " + msg);
    }
    Image img(w, h);
    for (std::size_t i = 0; i < std::size_t(w) * h; ++i)
        for (int c = 0; c < 3; ++c)
            img.rgb[3 * i + c] = data[4 * i + c];
    std::free(data);
    return img;
}

} // namespace smallmlt

namespace smallmlt {

Image read_image(const std::string& path) {
    switch (image_format_of(path, "")) {
    case ImageFormat::Pfm:
        return read_pfm(path);
    case ImageFormat::Exr:
        return read_exr(path);
    default:
        throw UsageError(path + ": only .pfm and .exr images hold linear radiance to compare");
    }
}

} // namespace smallmlt
