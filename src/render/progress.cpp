#include "render/progress.hpp"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace smallmlt {

Progress::Progress(bool enabled) : enabled_(enabled && isatty(STDERR_FILENO)) {}

Progress::~Progress() {
    finish();
}

void Progress::update(double fraction, const std::string& detail) {
    if (!enabled_) return;
    constexpr int kWidth = 30;
    int filled = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kWidth);
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "\r[%s] %3d%% %s\033[K", bar.c_str(),
                 static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 100), detail.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::finish() {
    if (!drawn_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
}

} // namespace smallmlt
