// Error against a reference image during a render (--reference, --log):
// MSE and relative MSE on linear RGB over the whole film, MSE over the
// pixels that --reference-mask leaves (mse_unlit) and the MSE of 8x8 and of
// 32x32 block means (block8_mse, block32_mse), the definitions of `smallmlt
// compare` (src/image/image_metrics.hpp). The log is a CSV with one row per
// interval of render time, "seconds,samples_per_pixel,samples,mse,rel_mse,
// mse_unlit,block8_mse,block32_mse", mse_unlit an empty field without a mask; it is written to a
// temporary file and renamed into place when the render ends, so a failed
// render leaves no log behind.
#pragma once
#include "base/interrupt.hpp"
#include "image/image.hpp"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

namespace smallmlt {

struct ErrorSample {
    double seconds = 0; // render time: measuring is not counted
    double spp = 0;     // samples (PT) or mutations (MLT) per pixel
    double mse = 0, rel_mse = 0;
    double mse_unlit = 0; // 0 without a mask
    double block8_mse = 0, block32_mse = 0;
};

class ConvergenceLog {
  public:
    // `log_path` may be empty: then only the final error is kept; so may
    // `mask_path`: then there is no mse_unlit. Throws InputError if the
    // reference or the mask cannot be read or does not match the film.
    ConvergenceLog(const std::string& reference_path, const std::string& mask_path,
                   const std::string& log_path, double interval_s, int width, int height);
    ~ConvergenceLog();
    ConvergenceLog(const ConvergenceLog&) = delete;
    ConvergenceLog& operator=(const ConvergenceLog&) = delete;

    // True when a row is owed at this render time.
    bool due(double render_s) const { return log_ && render_s >= next_s_; }
    // Measures `img` and appends a row.
    void record(double render_s, double spp, const Image& img);
    // Final row (unless the last one was at the same point) and the file
    // moved into place.
    void finish(double render_s, double spp, const Image& img);
    const ErrorSample& last() const { return last_; }
    bool has_mask() const { return !mask_path_.empty(); }

  private:
    Image reference_, mask_;
    std::string mask_path_;
    std::string log_path_, tmp_path_;
    std::FILE* log_ = nullptr;
    std::unique_ptr<TempFileGuard> tmp_guard_;
    double interval_s_, next_s_;
    std::uint64_t pixels_;
    ErrorSample last_;
    bool measured_ = false;
};

} // namespace smallmlt
