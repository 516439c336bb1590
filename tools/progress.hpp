// A progress bar on standard error, for the commands that go through whole fonts.
#pragma once

#include <iostream>
#include <string>

namespace gf {

class Progress {
 public:
  explicit Progress(bool on) : on_(on) {}
  void show(const std::string& what, std::size_t done, std::size_t total) const {
    if (!on_ || total == 0) return;
    const int width = 30, filled = static_cast<int>(width * done / total);
    std::cerr << "\r" << what << " [" << std::string(static_cast<std::size_t>(filled), '=')
              << std::string(static_cast<std::size_t>(width - filled), ' ') << "] " << done << "/" << total << std::flush;
  }
  void clear() const {
    if (on_) std::cerr << "\r" << std::string(79, ' ') << "\r" << std::flush;
  }

 private:
  bool on_;
};

}  // namespace gf
