#include "io/TradeoffTable.h"

#include <algorithm>
#include <cctype>
#include <fstream>
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

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
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

std::string MeasuredConfiguration::label() const {
  std::string out = method + ", " + body + ", progressive " + progressive;
  if (resolution != 1.0) out += ", sections x" + std::to_string(resolution);
  return out;
}

std::vector<MeasuredConfiguration> readTradeoffTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::string line;
  std::getline(in, line);
  if (line.rfind("method,body,progressive,resolution,garments,worst_mean_dev_pct_height,total_median_wall_s", 0) != 0)
    throw std::runtime_error(path + ": not a tradeoff table (its first line is \"" + line + "\")");
  std::vector<MeasuredConfiguration> table;
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
    ClothParameters probe;
    try {
      applyMethod(c.method, probe);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(where + ": " + e.what());
    }
    table.push_back(std::move(c));
  }
  return table;
}

std::optional<MeasuredConfiguration> fastestWithin(const std::vector<MeasuredConfiguration>& table, double tolerance,
                                                   const std::function<bool(const MeasuredConfiguration&)>& usable) {
  std::optional<MeasuredConfiguration> best;
  for (const MeasuredConfiguration& c : table)
    if (c.worstMeanDeviation <= tolerance && usable(c) && (!best || c.totalWall < best->totalWall)) best = c;
  return best;
}

ScheduleText parseScheduleText(const std::string& text) {
  ScheduleText s;
  std::stringstream in(text);
  char colon = 0;
  if (!(in >> s.beginShare >> colon >> s.rate) || colon != ':' || !(in >> std::ws).eof() ||
      !(s.beginShare >= 0.0 && s.beginShare <= 1.0) || !(s.rate >= 0.0))
    throw std::invalid_argument("schedule \"" + text + "\": expected BEGIN_SHARE:RATE, share in [0, 1], rate >= 0");
  return s;
}

void applyMethod(const std::string& method, ClothParameters& p) {
  const std::vector<std::string> parts = [&] {
    std::vector<std::string> out;
    std::stringstream in(method);
    for (std::string part; std::getline(in, part, ':');) out.push_back(lower(part));
    return out;
  }();
  const auto bad = [&](const std::string& why) {
    return std::invalid_argument("method \"" + method + "\": " + why +
                                 " (expected INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G])");
  };
  if (parts.size() != 2 && parts.size() != 4) throw bad("wrong number of parts");
  const std::string integrator = parts[0].substr(0, parts[0].find('+'));
  const std::string contacts =
      parts[0].find('+') == std::string::npos ? "constraints" : parts[0].substr(parts[0].find('+') + 1);
  if (integrator == "heun")
    p.integrator = Integrator::Heun;
  else if (integrator == "euler")
    p.integrator = Integrator::ExplicitEuler;
  else if (integrator == "symplectic")
    p.integrator = Integrator::SymplecticEuler;
  else if (integrator == "implicit")
    p.integrator = Integrator::Implicit;
  else
    throw bad("no integrator " + integrator);
  if (contacts == "constraints")
    p.implicitSolver.contacts = ContactModel::Constraints;
  else if (contacts == "penalty")
    p.implicitSolver.contacts = ContactModel::Penalty;
  else
    throw bad("no contact model " + contacts);
  const auto parse = [&](const std::string& text) {
    const std::optional<double> value = readNumber(text);
    if (!value) throw bad("\"" + text + "\" is not a number");
    return *value;
  };
  p.timeStep = parse(parts[1]);
  p.accelerationLimiter = AccelerationLimiter::None;
  if (parts.size() == 4) {
    if (parts[2] == "clamp")
      p.accelerationLimiter = AccelerationLimiter::Clamp;
    else if (parts[2] == "tanh")
      p.accelerationLimiter = AccelerationLimiter::Tanh;
    else if (parts[2] != "none")
      throw bad("no limiter " + parts[2]);
    p.accelerationLimit = parse(parts[3]);
  }
  if (!(p.timeStep > 0.0)) throw bad("the time step must be > 0");
}

}  // namespace figment
