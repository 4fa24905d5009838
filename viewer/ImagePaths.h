#pragma once
// figment-view's output names when one run writes several images (--view repeated,
// --turntable, --frames).

#include <optional>
#include <string>
#include <vector>

namespace figment::viewer {

// The paths of `count` images written for `-o output`, numbered from 0:
//  - a printf-style number in the name ("frame-%d.png", "frame-%03d.png": one %d,
//    optionally zero-padded to a width of 1 to 9) takes each image's number, also when
//    there is only one image;
//  - otherwise one image is `output` itself, and several are numbered before the
//    extension, zero-padded so they sort: "out.png" -> "out-0.png" ... "out-7.png"
//    (8 images), "out-00.png" ... "out-39.png" (40 images).
// Nullopt when the name holds more than one %d, or a malformed one ("%5d", "%0d").
std::optional<std::vector<std::string>> imagePaths(const std::string& output, int count);

}  // namespace figment::viewer
