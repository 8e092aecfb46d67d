#include "pedtrack/progress.h"

#include <unistd.h>

#include <cstdio>

namespace pedtrack {

Progress::Progress(std::string label, bool enabled)
    : label_(std::move(label)),
      enabled_(enabled),
      tty_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void Progress::update(std::size_t items, double fraction) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  // A terminal redraws 5 times a second; a log gets a line every 5 s.
  const double every = tty_ ? 0.2 : 5.0;
  if (std::chrono::duration<double>(now - last_).count() < every) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (tty_ && fraction >= 0) {
    const int width = 30, filled = static_cast<int>(fraction * width + 0.5);
    std::fprintf(stderr, "\r%s [%.*s%*s] %5.1f%% %zu frames %.1fs", label_.c_str(), filled,
                 "##############################", width - filled, "", 100 * fraction, items,
                 elapsed);
  } else if (tty_) {
    std::fprintf(stderr, "\r%s %zu frames %.1fs", label_.c_str(), items, elapsed);
  } else if (fraction >= 0) {
    std::fprintf(stderr, "%s: %zu frames, %.0f%%, %.1fs\n", label_.c_str(), items, 100 * fraction,
                 elapsed);
  } else {
    std::fprintf(stderr, "%s: %zu frames, %.1fs\n", label_.c_str(), items, elapsed);
  }
  std::fflush(stderr);
}

void Progress::done(std::size_t items) {
  if (!enabled_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "%s%s: %zu frames in %.2fs\n", tty_ ? "\r\033[K" : "", label_.c_str(), items,
               elapsed);
}

}  // namespace pedtrack
