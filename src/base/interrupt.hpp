// SIGINT and SIGTERM during a render. The first signal asks the render loop
// to stop after the current pass; the image so far is then written as usual
// and smallmlt exits with kExitInterrupted. A second signal exits at once
// with 128 + signal, after removing the temporary files being written, so no
// file is left half-written under either name.
#pragma once
#include <string>

namespace smallmlt {

constexpr int kExitInterrupted = 3;

// Installs the handlers for its lifetime.
class InterruptGuard {
  public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;
};

bool interrupt_requested();

// A file being written under a temporary name, removed by a second signal.
class TempFileGuard {
  public:
    explicit TempFileGuard(const std::string& path);
    ~TempFileGuard();
    TempFileGuard(const TempFileGuard&) = delete;
    TempFileGuard& operator=(const TempFileGuard&) = delete;

  private:
    int slot_;
};

} // namespace smallmlt
