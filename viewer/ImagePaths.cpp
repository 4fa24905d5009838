#include "viewer/ImagePaths.h"

#include <filesystem>
#include <regex>

namespace figment::viewer {

namespace {

std::string padded(int number, int width) {
  std::string digits = std::to_string(number);
  if (static_cast<int>(digits.size()) < width) digits.insert(0, width - digits.size(), '0');
  return digits;
}

}  // namespace

std::optional<std::vector<std::string>> imagePaths(const std::string& output, int count) {
  // Any '%' followed by digits and 'd' is meant as a number: accept only the forms
  // documented, so that "%5d" (space-padded, spaces in file names) is refused, not
  // written literally.
  static const std::regex anyNumber(R"(%[0-9]*d)");
  static const std::regex documented(R"(%(?:0([1-9]))?d)");
  const auto numbers =
      std::distance(std::sregex_iterator(output.begin(), output.end(), anyNumber), std::sregex_iterator());
  std::vector<std::string> paths;
  if (numbers > 1) return std::nullopt;
  if (numbers == 1) {
    std::smatch found, form;
    std::regex_search(output, found, anyNumber);
    const std::string text = found.str();
    if (!std::regex_match(text, form, documented)) return std::nullopt;
    const int width = form[1].matched ? std::stoi(form[1]) : 1;
    for (int i = 0; i < count; ++i) paths.push_back(found.prefix().str() + padded(i, width) + found.suffix().str());
    return paths;
  }
  if (count == 1) return std::vector<std::string>{output};
  const std::filesystem::path path(output);
  const std::string extension = path.extension().string();
  const std::string stem = output.substr(0, output.size() - extension.size());
  const int width = static_cast<int>(std::to_string(count - 1).size());
  for (int i = 0; i < count; ++i) paths.push_back(stem + "-" + padded(i, width) + extension);
  return paths;
}

}  // namespace figment::viewer
