#include "io/SizeChartFile.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace figment {

namespace {

// One line's size; throws std::runtime_error naming the line and field.
ChartSize parseSize(const std::string& text, const std::string& where) {
  std::istringstream fields(text);
  ChartSize size;
  std::string sex;
  fields >> sex >> size.name >> size.number;
  if (sex != "female" && sex != "male") throw std::runtime_error(where + ": sex '" + sex + "' is not female or male");
  size.sex = sex == "male" ? Sex::Male : Sex::Female;
  const char* names[] = {"stature", "bust", "waist", "hip"};
  double* values[] = {&size.stature, &size.bust, &size.waist, &size.hip};
  for (int i = 0; i < 4; ++i) {
    std::string word;
    if (!(fields >> word)) throw std::runtime_error(where + ": no " + names[i]);
    try {
      size_t used = 0;
      *values[i] = std::stod(word, &used);
      if (used != word.size()) throw std::invalid_argument(word);
    } catch (const std::exception&) {
      throw std::runtime_error(where + ": " + names[i] + " '" + word + "' is not a number");
    }
  }
  if (std::string extra; fields >> extra) throw std::runtime_error(where + ": unexpected '" + extra + "'");
  return size;
}

}  // namespace

std::string defaultSizeChartPath() {
  return FIGMENT_SIZE_CHART_DEFAULT;
}

SizeChart readSizeChart(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be opened");
  std::vector<ChartSize> sizes;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    sizes.push_back(parseSize(line, path + ":" + std::to_string(number)));
  }
  try {
    return SizeChart(std::move(sizes));
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
}

}  // namespace figment
