#include "viewer/ImagePlan.h"

#include "viewer/ImagePaths.h"

namespace figment::viewer {

std::optional<ImagePlan> planImages(const ImageOptions& options, ImageOptionError& error) {
  const auto refuse = [&error](std::string option, std::string message) {
    error = {std::move(option), std::move(message)};
    return std::nullopt;
  };
  ImagePlan plan;
  const auto size = parseImageSize(options.size);
  if (!size) return refuse("--size", "'" + options.size + "' is not WxH with 1 to 16384 pixels each (e.g. 800x600)");
  plan.size = *size;
  for (const std::string& text : options.views) {
    const std::optional<ViewDirection> view = parseViewDirection(text);
    if (!view)
      return refuse("--view", "'" + text + "' is not front, back, left, right or AZ,EL in degrees with -90 < EL < 90");
    plan.views.push_back(view);
  }
  if (!options.turntable.empty()) {
    const std::optional<int> count = parseTurntableCount(options.turntable);
    if (!count)
      return refuse("--turntable", "'" + options.turntable + "' is not a whole number of views from 1 to " +
                                       std::to_string(kMaxTurntableViews));
    if (plan.views.size() > 1)
      return refuse("--turntable",
                    "takes at most one --view (where it starts), not " + std::to_string(plan.views.size()));
    const std::vector<ViewDirection> around =
        turntableViews(*count, plan.views.empty() ? std::nullopt : plan.views.front());
    plan.views.assign(around.begin(), around.end());
    plan.oneDistance = true;
  }
  if (plan.views.empty()) plan.views.push_back(std::nullopt);
  if (!options.frames.empty()) {
    const std::optional<std::vector<double>> times = parseFrameTimes(options.frames);
    if (!times)
      return refuse("--frames", "'" + options.frames + "' is not T0:T1:N with 0 <= T0 <= T1 seconds and 1 <= N <= " +
                                    std::to_string(kMaxFrames) + " frames (e.g. 0:4:40)");
    if (plan.views.size() > 1) return refuse("--frames", "takes one view, not " + std::to_string(plan.views.size()));
    plan.frameTimes = *times;
  }
  const int count = static_cast<int>(plan.frameTimes.empty() ? plan.views.size() : plan.frameTimes.size());
  const std::optional<std::vector<std::string>> paths = imagePaths(options.output, count);
  if (!paths) return refuse("--output", "'" + options.output + "' may hold one number, %d or %0Nd with N from 1 to 9");
  plan.paths = *paths;
  return plan;
}

}  // namespace figment::viewer
