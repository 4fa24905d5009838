#include "sim/core/ParameterChecks.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace figment {

std::optional<double> wholeNumber(const std::string& text) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return used == text.size() ? std::optional<double>(value) : std::nullopt;
}

std::string formatNumber(double value) {
  char buffer[64];
  auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::to_string(value);
}

namespace {
[[noreturn]] void fail(const char* field, double value, const std::string& rule) {
  throw std::invalid_argument(std::string(field) + " = " + formatNumber(value) + " " + rule);
}
}  // namespace

void requireFinite(const char* field, double value) {
  if (!std::isfinite(value)) fail(field, value, "must be a finite number");
}

void requirePositive(const char* field, double value) {
  requireFinite(field, value);
  if (!(value > 0.0)) fail(field, value, "must be > 0");
}

void requireNonNegative(const char* field, double value) {
  requireFinite(field, value);
  if (!(value >= 0.0)) fail(field, value, "must be >= 0");
}

void requireOpenRange(const char* field, double value, double low, double high) {
  requireFinite(field, value);
  if (!(value > low && value < high))
    fail(field, value, "must be in (" + formatNumber(low) + ", " + formatNumber(high) + ")");
}

}  // namespace figment
