#pragma once
// Checks for configuration values at sim/'s API: each throws std::invalid_argument with
// a message naming the field and the value ("thickness = -0.001 must be > 0"), which the
// node kit and the viewer pass on to the user unchanged.

#include <optional>
#include <string>

namespace figment {

void requirePositive(const char* field, double value);
void requireNonNegative(const char* field, double value);
void requireOpenRange(const char* field, double value, double low, double high);
void requireFinite(const char* field, double value);

// The whole of `text` as a number ("0.05", "1.5e-4"), if it is one: nullopt for "", "x" or
// "0.05s".
std::optional<double> wholeNumber(const std::string& text);

// Shortest text that reads back as `value` ("0.001", "5e-04", "-1e-05").
std::string formatNumber(double value);

}  // namespace figment
