#pragma once
// figment-view's progress bar: one line on a terminal, redrawn in place while an engine
// drapes, erased when it is done. Written only when the stream is a terminal (isatty),
// so redirected output (tests, CI, logs) is what it was without it.

#include <cstdio>
#include <string>

namespace figment::viewer {

// "ClothEngine 'Drape' [###############...............]    2.5 / 5 s simulated, 1.2 s":
// the bar, `width` characters, filled by the share of maxSeconds simulated (held within
// [0, 1]; nothing when maxSeconds is not positive), then the times.
std::string progressBarLine(const std::string& label, double simulatedSeconds, double maxSeconds, double wallSeconds,
                            int width = 30);

class ProgressBar {
 public:
  // Draws on `stream` only when it is a terminal.
  explicit ProgressBar(std::FILE* stream);
  ~ProgressBar() { clear(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  bool shown() const { return terminal_; }
  // Redraws the line (carriage return, the bar, the rest of the old line erased).
  void draw(const std::string& line);
  // Erases the line, so what is written next starts at the line's beginning.
  void clear();

 private:
  std::FILE* stream_;
  bool terminal_;
  bool drawn_ = false;
};

}  // namespace figment::viewer
