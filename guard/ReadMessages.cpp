#include "guard/ReadMessages.h"

#include <Inventor/errors/SoReadError.h>

#include <filesystem>
#include <regex>

namespace figment::guard {

namespace {

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code ec;
  return a == b || std::filesystem::equivalent(a, b, ec);
}

// Posts `text` ("Coin warning in SoFile::readNamedFile(): ...") again, with its severity, to
// whichever handler is installed: the same words reach it as the first time.
void repost(SoDebugError::Severity severity, const std::string& text) {
  static const std::regex parts(R"(^Coin \w+ in (.*?)\(\): ([\s\S]*)$)");
  std::smatch m;
  const bool split = std::regex_match(text, m, parts);
  const std::string source = split ? std::string(m[1]) : "figment::guard";
  const std::string message = split ? std::string(m[2]) : text;
  if (severity == SoDebugError::ERROR)
    SoDebugError::post(source.c_str(), "%s", message.c_str());
  else if (severity == SoDebugError::WARNING)
    SoDebugError::postWarning(source.c_str(), "%s", message.c_str());
  else
    SoDebugError::postInfo(source.c_str(), "%s", message.c_str());
}

}  // namespace

ReadMessages::ReadMessages()
    : readHandler_(SoReadError::getHandlerCallback()),
      readData_(SoReadError::getHandlerData()),
      debugHandler_(SoDebugError::getHandlerCallback()),
      debugData_(SoDebugError::getHandlerData()) {
  SoReadError::setHandlerCallback(onReadError, this);
  SoDebugError::setHandlerCallback(onDebugMessage, this);
}

ReadMessages::~ReadMessages() {
  SoReadError::setHandlerCallback(readHandler_, readData_);
  SoDebugError::setHandlerCallback(debugHandler_, debugData_);
}

void ReadMessages::onReadError(const SoError* error, void* self) {
  // "Coin read error: <message>\n\tOccurred at line   4 in <file>"
  static const std::regex location(R"(([\s\S]*?)\s*Occurred at line\s+(\d+) in (.*)\s*$)");
  const std::string text = error->getDebugString().getString();
  std::smatch m;
  auto& errors = static_cast<ReadMessages*>(self)->readErrors_;
  if (std::regex_match(text, m, location))
    errors.push_back({oneLine(m[1]), m[3], std::stoi(m[2])});
  else
    errors.push_back({oneLine(text), {}, 0});
}

void ReadMessages::onDebugMessage(const SoError* error, void* self) {
  const auto* debug = static_cast<const SoDebugError*>(error);
  static_cast<ReadMessages*>(self)->warnings_.push_back({debug->getSeverity(), error->getDebugString().getString()});
}

std::vector<std::string> ReadMessages::readErrors(const std::string& scene) const {
  std::vector<std::string> out;
  for (const ReadError& e : readErrors_) {
    std::string line = e.line > 0 ? "line " + std::to_string(e.line) + ": " + e.message : e.message;
    if (!e.file.empty() && !sameFile(e.file, scene)) line += " (in " + e.file + ")";
    out.push_back(line);
  }
  return out;
}

void ReadMessages::passOnWarnings() {
  SoDebugError::setHandlerCallback(debugHandler_, debugData_);
  for (const Warning& warning : warnings_) repost(warning.severity, warning.text);
  warnings_.clear();
  SoDebugError::setHandlerCallback(onDebugMessage, this);
}

std::string ReadMessages::oneLine(const std::string& message) {
  // Compiled once: a scene with many read errors passes every one through here.
  static const std::regex prefix(R"(^Coin (read )?(error|warning|info)( in \S+\(\))?:\s*)");
  static const std::regex lineBreak(R"(\s*\n\s*)");
  std::string text = std::regex_replace(message, prefix, "");
  text = std::regex_replace(text, lineBreak, "; ");
  while (!text.empty() && (text.back() == ' ' || text.back() == ';')) text.pop_back();
  return text;
}

}  // namespace figment::guard
