#include "render/convergence_log.hpp"

#include "base/error.hpp"
#include "image/image_metrics.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <unistd.h>

namespace smallmlt {

namespace {

// The image file given to `flag`, which must be of the film's size.
Image read_film_image(const std::string& flag, const std::string& path, int width, int height) {
    Image img = read_image(path);
    if (img.width != width || img.height != height)
        throw InputError(flag + " " + path + ": image is " + std::to_string(img.width) + "x" +
                         std::to_string(img.height) + ", the film " + std::to_string(width) + "x" +
                         std::to_string(height));
    return img;
}

} // namespace

ConvergenceLog::ConvergenceLog(const std::string& reference_path, const std::string& mask_path,
                               const std::string& log_path, double interval_s, int width,
                               int height)
    : reference_(read_film_image("--reference", reference_path, width, height)),
      mask_path_(mask_path), log_path_(log_path), interval_s_(interval_s), next_s_(interval_s),
      pixels_(std::uint64_t(width) * std::uint64_t(height)) {
    if (has_mask()) mask_ = read_film_image("--reference-mask", mask_path_, width, height);
    if (log_path_.empty()) return;
    std::size_t slash = log_path_.find_last_of('/');
    std::size_t base = slash == std::string::npos ? 0 : slash + 1;
    tmp_path_ = log_path_.substr(0, base) + ".tmp-" + std::to_string(getpid()) + "-" +
                log_path_.substr(base);
    tmp_guard_ = std::make_unique<TempFileGuard>(tmp_path_);
    log_ = std::fopen(tmp_path_.c_str(), "w");
    if (!log_) throw InputError("--log " + log_path_ + ": " + std::strerror(errno));
    std::fputs("seconds,samples_per_pixel,samples,mse,rel_mse,mse_unlit,block8_mse,block32_mse\n",
               log_);
    std::fflush(log_);
}

ConvergenceLog::~ConvergenceLog() {
    if (!log_) return;
    std::fclose(log_);
    std::remove(tmp_path_.c_str());
}

void ConvergenceLog::record(double render_s, double spp, const Image& img) {
    last_ = {render_s,
             spp,
             image_mse(img, reference_),
             image_rel_mse(img, reference_),
             has_mask() ? image_mse_excluding(img, reference_, mask_, mask_path_) : 0.0,
             image_block_mse(img, reference_, kErrorBlock),
             image_block_mse(img, reference_, kErrorBlockWide)};
    measured_ = true;
    if (!log_) return;
    char unlit[32] = "";
    if (has_mask()) std::snprintf(unlit, sizeof unlit, "%.9g", last_.mse_unlit);
    std::fprintf(log_, "%.6f,%.6g,%llu,%.9g,%.9g,%s,%.9g,%.9g\n", render_s, spp,
                 static_cast<unsigned long long>(std::llround(spp * double(pixels_))), last_.mse,
                 last_.rel_mse, unlit, last_.block8_mse, last_.block32_mse);
    std::fflush(log_);
    // At least the interval after this row: on a grid of the interval, a pass
    // ending just before a grid point and the next just after it gave two
    // rows a few microseconds apart, printed with the same seconds.
    next_s_ = render_s + interval_s_;
}

void ConvergenceLog::finish(double render_s, double spp, const Image& img) {
    if (!measured_ || last_.spp != spp) record(render_s, spp, img);
    if (!log_) return;
    bool ok = std::fclose(log_) == 0;
    log_ = nullptr;
    if (!ok || std::rename(tmp_path_.c_str(), log_path_.c_str()) != 0) {
        std::string why = std::strerror(errno);
        std::remove(tmp_path_.c_str());
        throw InputError("--log " + log_path_ + ": cannot write: " + why);
    }
}

} // namespace smallmlt
