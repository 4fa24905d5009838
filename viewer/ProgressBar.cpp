#include "viewer/ProgressBar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace figment::viewer {

std::string progressBarLine(const std::string& label, double simulatedSeconds, double maxSeconds, double wallSeconds,
                            int width) {
  const double fraction =
      maxSeconds > 0.0 && std::isfinite(simulatedSeconds) ? std::clamp(simulatedSeconds / maxSeconds, 0.0, 1.0) : 0.0;
  const int filled = static_cast<int>(std::floor(fraction * width));
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, "] %6.3g / %.3g s simulated, %.1f s", simulatedSeconds, maxSeconds,
                wallSeconds);
  return label + " [" + std::string(filled, '#') + std::string(width - filled, '.') + numbers;
}

ProgressBar::ProgressBar(std::FILE* stream) : stream_(stream), terminal_(isatty(fileno(stream)) == 1) {}

void ProgressBar::draw(const std::string& line) {
  if (!terminal_) return;
  // \033[K erases what a longer previous line left on the right.
  std::fprintf(stream_, "\r%s\033[K", line.c_str());
  std::fflush(stream_);
  drawn_ = true;
}

void ProgressBar::clear() {
  if (!terminal_ || !drawn_) return;
  std::fprintf(stream_, "\r\033[K");
  std::fflush(stream_);
  drawn_ = false;
}

}  // namespace figment::viewer
