#include "viewer/CoinMessages.h"

#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>

#include <filesystem>
#include <iostream>
#include <regex>

namespace figment::viewer {

namespace {

struct ReadError {
  std::string message;
  std::string file;
  int line = 0;
};

std::vector<ReadError>& readErrors() {
  static std::vector<ReadError> errors;
  return errors;
}

void onReadError(const SoError* error, void*) {
  // "Coin read error: <message>\n\tOccurred at line   4 in <file>"
  static const std::regex location(R"(([\s\S]*?)\s*Occurred at line\s+(\d+) in (.*)\s*$)");
  const std::string text = error->getDebugString().getString();
  std::smatch m;
  if (std::regex_match(text, m, location))
    readErrors().push_back({CoinMessages::oneLine(m[1]), m[3], std::stoi(m[2])});
  else
    readErrors().push_back({CoinMessages::oneLine(text), {}, 0});
}

struct HeldWarnings {
  bool holding = false;
  std::vector<std::string> lines;
};

HeldWarnings& heldWarnings() {
  static HeldWarnings held;
  return held;
}

void onDebugMessage(const SoError* error, void*) {
  const std::string text = error->getDebugString().getString();
  // Coin asks GLX whether rendering is direct even when no GLX context exists.
  if (text.find("glxglue_isdirect") != std::string::npos) return;
  // A ClothEngine's error is its lastError(), which figment-view reports itself.
  if (text.find("ClothEngine::evaluate") != std::string::npos) return;
  const std::string line = "figment-view: warning: " + CoinMessages::oneLine(text);
  if (heldWarnings().holding)
    heldWarnings().lines.push_back(line);
  else
    std::cerr << line << "\n";
}

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  return a == b || std::filesystem::equivalent(a, b, ec);
}

}  // namespace

void CoinMessages::install() {
  SoReadError::setHandlerCallback(onReadError, nullptr);
  SoDebugError::setHandlerCallback(onDebugMessage, nullptr);
}

void CoinMessages::holdWarnings() { heldWarnings().holding = true; }

void CoinMessages::releaseWarnings(bool print) {
  HeldWarnings& held = heldWarnings();
  if (print)
    for (const std::string& line : held.lines) std::cerr << line << "\n";
  held = {};
}

std::vector<std::string> CoinMessages::takeReadErrors(const std::string& scene) {
  std::vector<std::string> out;
  for (const auto& e : readErrors()) {
    std::string line = e.line > 0 ? "line " + std::to_string(e.line) + ": " + e.message : e.message;
    if (!e.file.empty() && !sameFile(e.file, scene)) line += " (in " + e.file + ")";
    out.push_back(line);
  }
  readErrors().clear();
  return out;
}

std::string CoinMessages::oneLine(const std::string& message) {
  // Compiled once: a scene with many read errors passes every one through here.
  static const std::regex prefix(R"(^Coin (read )?(error|warning|info)( in \S+\(\))?:\s*)");
  static const std::regex lineBreak(R"(\s*\n\s*)");
  std::string text = std::regex_replace(message, prefix, "");
  text = std::regex_replace(text, lineBreak, "; ");
  while (!text.empty() && (text.back() == ' ' || text.back() == ';')) text.pop_back();
  return text;
}

}  // namespace figment::viewer
