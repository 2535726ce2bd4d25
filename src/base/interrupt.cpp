#include "base/interrupt.hpp"

#include <csignal>
#include <cstring>
#include <unistd.h>

namespace smallmlt {

namespace {

constexpr int kSlots = 8;
constexpr std::size_t kPathMax = 4096;

volatile std::sig_atomic_t g_requested = 0;
char g_paths[kSlots][kPathMax];
volatile std::sig_atomic_t g_used[kSlots];

struct sigaction g_old_int, g_old_term;

void on_signal(int sig) {
    if (!g_requested) {
        g_requested = 1;
        static const char msg[] =
            "\nsmallmlt: stopping after the current pass (signal again to quit at once)\n";
        ssize_t rc = write(STDERR_FILENO, msg, sizeof msg - 1);
        (void)rc;
        return;
    }
    for (int i = 0; i < kSlots; ++i)
        if (g_used[i]) unlink(g_paths[i]);
    _exit(128 + sig);
}

} // namespace

InterruptGuard::InterruptGuard() {
    g_requested = 0;
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &g_old_int);
    sigaction(SIGTERM, &sa, &g_old_term);
}

InterruptGuard::~InterruptGuard() {
    sigaction(SIGINT, &g_old_int, nullptr);
    sigaction(SIGTERM, &g_old_term, nullptr);
}

bool interrupt_requested() {
    return g_requested != 0;
}

TempFileGuard::TempFileGuard(const std::string& path) : slot_(-1) {
    if (path.size() >= kPathMax) return;
    for (int i = 0; i < kSlots; ++i)
        if (!g_used[i]) {
            std::memcpy(g_paths[i], path.c_str(), path.size() + 1);
            g_used[i] = 1;
            slot_ = i;
            return;
        }
}

TempFileGuard::~TempFileGuard() {
    if (slot_ >= 0) g_used[slot_] = 0;
}

} // namespace smallmlt
