#pragma once
// What figment-view's image options ask for (-o, --size, --view repeated, --turntable,
// --frames), checked before anything is read: the views or frame times and a path for
// each image.

#include <optional>
#include <string>
#include <vector>

#include "viewer/ViewOptions.h"

namespace figment::viewer {

struct ImageOptions {
  std::string output{};              // -o
  std::string size{};                // --size
  std::vector<std::string> views{};  // --view, in the order given
  std::string turntable{};           // --turntable; "" = none
  std::string frames{};              // --frames; "" = none
};

struct ImagePlan {
  ImageSize size;
  std::vector<std::optional<ViewDirection>> views;  // nullopt: the scene's camera
  std::vector<double> frameTimes;                   // s; empty: the drape itself, an image per view
  std::vector<std::string> paths;                   // an image per frame, else per view (imagePaths)
  // --turntable: the views keep one camera distance, so the figure keeps its size as
  // it turns (each --view otherwise frames the scene as closely as it can).
  bool oneDistance = false;
};

// The option at fault and what is wrong with its value, as figment-view says it.
struct ImageOptionError {
  std::string option;
  std::string message;
};

// The plan, or nullopt with `error`: a bad size, view, turntable count or frame span;
// --turntable with more than one --view (one gives its start); --frames with more than
// one view; an output name with an unusable number (imagePaths).
std::optional<ImagePlan> planImages(const ImageOptions& options, ImageOptionError& error);

}  // namespace figment::viewer
