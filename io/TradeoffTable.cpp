#include "io/TradeoffTable.h"

#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace figment {

namespace {
std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

// The whole of `text` as a number, if it is one.
std::optional<double> readNumber(const std::string& text) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return used == text.size() ? std::optional<double>(value) : std::nullopt;
}

double number(const std::string& text, const std::string& where) {
  const std::optional<double> value = readNumber(text);
  if (!value) throw std::runtime_error(where + ": \"" + text + "\" is not a number");
  return *value;
}
}  // namespace

MethodTable readTradeoffTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::string line;
  std::getline(in, line);
  if (line.rfind("method,body,progressive,resolution,garments,worst_mean_dev_pct_height,total_median_wall_s", 0) != 0)
    throw std::runtime_error(path + ": not a tradeoff table (its first line is \"" + line + "\")");
  MethodTable table{path, {}};
  for (int number_ = 2; std::getline(in, line); ++number_) {
    if (line.empty()) continue;
    const std::string where = path + ":" + std::to_string(number_);
    const std::vector<std::string> cells = splitCsv(line);
    if (cells.size() != 7)
      throw std::runtime_error(where + ": expected 7 columns, found " + std::to_string(cells.size()));
    MeasuredConfiguration c{cells[0], cells[1], cells[2]};
    c.resolution = number(cells[3], where);
    c.garments = static_cast<int>(number(cells[4], where));
    c.worstMeanDeviation = number(cells[5], where);
    c.totalWall = number(cells[6], where);
    try {
      DrapeMethod::parse(c.method);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(where + ": " + e.what());
    }
    table.configurations.push_back(std::move(c));
  }
  return table;
}

}  // namespace figment
