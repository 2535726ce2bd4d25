// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once
#include <string>

namespace smallmlt {

class Progress {
  public:
    explicit Progress(bool enabled);
    ~Progress();
    // fraction in [0,1]; `detail` follows the bar (e.g. "12/64 spp").
    void update(double fraction, const std::string& detail);
    void finish();

  private:
    bool enabled_;
    bool drawn_ = false;
};

} // namespace smallmlt
