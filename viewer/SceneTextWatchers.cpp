#include "viewer/SceneTextWatchers.h"

#include <cerrno>
#include <algorithm>
#include <cstdlib>

namespace figment::viewer {

const OpenDefinitions::Definition* OpenDefinitions::see(const Token& t, int depth) {
    if (t.kind == Token::kClose)
      while (!open_.empty() && open_.back().depth > depth) open_.pop_back();
    const Expect expected = expect_;
    expect_ = Expect::kNothing;
    if (t.kind == Token::kOpen) {
      if (expected == Expect::kBody) open_.push_back({pending_, pendingLine_, depth});
      return nullptr;
    }
    if (t.kind != Token::kWord) return nullptr;
    switch (expected) {
      case Expect::kDefName:
        pending_ = std::string(t.word), pendingLine_ = t.line, latest_[pending_] = t.line;
        expect_ = Expect::kType;
        return nullptr;
      case Expect::kType:
        expect_ = Expect::kBody;
        return nullptr;
      case Expect::kUseName: {
        const auto latest = latest_.find(std::string(t.word));
        if (latest == latest_.end()) return nullptr;
        for (const Definition& d : open_)
          if (d.name == t.word && d.line == latest->second) return &d;
        return nullptr;
      }
      default:
        if (t.word == "DEF") expect_ = Expect::kDefName;
        if (t.word == "USE") expect_ = Expect::kUseName;
        return nullptr;
    }
  }

const std::string* ExternProtoUrls::see(const Token& t, int depth) {
    const Stage stage = stage_;
    stage_ = Stage::kNone;
    const bool url = t.kind == Token::kString || t.kind == Token::kWord;
    switch (stage) {
      case Stage::kNone:
        if (t.kind == Token::kWord && t.word == "EXTERNPROTO") stage_ = Stage::kName;
        return nullptr;
      case Stage::kName:
        if (t.kind == Token::kWord) name_ = std::string(t.word), stage_ = Stage::kInterface;
        return nullptr;
      case Stage::kInterface:
        if (t.kind == Token::kOpen && t.word == "[") stage_ = Stage::kInInterface, interfaceDepth_ = depth;
        return nullptr;
      case Stage::kInInterface:
        stage_ = t.kind == Token::kClose && depth < interfaceDepth_ ? Stage::kUrl : Stage::kInInterface;
        return nullptr;
      case Stage::kUrl:
        if (t.kind == Token::kOpen && t.word == "[") stage_ = Stage::kFirstOfList;
        return url ? &name_ : nullptr;
      case Stage::kFirstOfList:
        return url ? &name_ : nullptr;
    }
    return nullptr;
  }

const OpenPrototypes::Prototype* OpenPrototypes::see(const Token& t, int depth) {
  const std::string_view before = lastWord_;
  lastWord_ = t.kind == Token::kWord ? t.word : std::string_view();
  if (t.kind == Token::kClose) {
    while (!open_.empty() && open_.back().body && depth <= open_.back().depth) open_.pop_back();
    return nullptr;
  }
  const Expect expected = expect_;
  expect_ = Expect::kNothing;
  if (expected == Expect::kName && t.kind == Token::kWord) {
    open_.push_back({std::string(t.word), t.line, depth, false});
    return nullptr;
  }
  if (t.kind == Token::kWord && t.word == "PROTO") expect_ = Expect::kName;
  if (t.kind != Token::kOpen) return nullptr;
  // A body opens with the first '{' one level below a PROTO whose interface has closed.
  if (t.word == "{" && !open_.empty() && !open_.back().body && depth == open_.back().depth + 1 &&
      before.empty()) {
    open_.back().body = true;
    return nullptr;
  }
  if (t.word == "{" && !before.empty())
    for (const Prototype& p : open_)
      if (p.name == before) return &p;
  return nullptr;
}

namespace {

bool isCounter(std::string_view word) {
  return word == "TimeCounter" || word == "SoTimeCounter" || word == "Counter" || word == "SoCounter";
}

// Whether Coin reads `word` into a short as 0: "0", "0x0", "-0", or 65536 and its multiples,
// which wrap to 0. A word that is not a whole number is Coin's read error to report.
bool shortZero(std::string_view word) {
  const std::string text(word);
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), &end, 0);
  if (end == text.c_str() || *end != '\0') return false;
  return errno == 0 && value % 65536 == 0;
}

}  // namespace

std::string CounterSteps::see(const Token& t, int depth) {
  const Expect expected = expect_;
  expect_ = Expect::kNothing;
  if (t.kind == Token::kClose && bodyDepth_ >= 0 && depth < bodyDepth_) bodyDepth_ = -1;
  if (expected == Expect::kBody && t.kind == Token::kOpen && t.word == "{") {
    type_ = pendingType_, bodyDepth_ = depth;
    return "";
  }
  if (t.kind != Token::kWord) return "";
  const std::string counter = std::string(type_) + " { step ";
  if ((expected == Expect::kStepValue || expected == Expect::kConnection) && t.word == "=")
    return counter + "= ... } takes its step from a connection: Coin divides by the step, and a step of 0 "
           "crashes it; give the step as a number";
  if (expected == Expect::kStepValue) {
    if (shortZero(t.word))
      return counter + std::string(t.word) + " } divides by zero: the step must not be 0 (or a multiple of 65536)";
    expect_ = Expect::kConnection;  // `step 1 = X.output` connects it as well
    return "";
  }
  if (bodyDepth_ >= 0 && depth == bodyDepth_ && t.word == "step") {
    expect_ = Expect::kStepValue;
    return "";
  }
  if (isCounter(t.word)) pendingType_ = t.word, expect_ = Expect::kBody;
  return "";
}

std::string ImageSizes::see(const Token& t) {
  if (wanted_ == 0) {
    if (t.kind != Token::kWord) return "";
    if (t.word == "images") field_ = t.word, wanted_ = 4;  // Texture3's SFImage3
    if (t.word == "image" || (t.word.size() == 9 && t.word.substr(0, 5) == "image" &&
                              (t.word.substr(5, 3) == "Pos" || t.word.substr(5, 3) == "Neg")))
      field_ = t.word, wanted_ = 3;  // Texture2, Image, BumpMap, VRML PixelTexture; TextureCubeMap's imagePosX...
    dimensions_.clear();
    return "";
  }
  const std::string text(t.word);
  char* end = nullptr;
  const long long value = t.kind == Token::kWord ? std::strtoll(text.c_str(), &end, 0) : 0;
  if (t.kind != Token::kWord || end == text.c_str() || *end != '\0') {
    wanted_ = 0;  // not an image size after all, or Coin's read error to report
    return "";
  }
  dimensions_.push_back(value);
  if (dimensions_.size() < wanted_) return "";
  wanted_ = 0;
  long long pixels = 1;
  std::string size;
  for (size_t i = 0; i + 1 < dimensions_.size(); ++i) {
    const auto read = static_cast<short>(dimensions_[i]);  // as Coin reads it, into a short
    if (read <= 0) return "";  // Coin refuses or reads an empty image
    pixels *= read;
    size += (i ? " x " : "") + std::to_string(read);
  }
  const size_t left = textSize_ - std::min(textSize_, t.end);
  if (static_cast<unsigned long long>(pixels) <= left / 2) return "";
  return std::string(field_) + " " + size + " declares " + std::to_string(pixels) + " pixels, more than the " +
         std::to_string(left) + " bytes left in the file hold (a number each)";
}

std::string ReaderHazards::see(const Token& t, int depth) {
  if (const OpenDefinitions::Definition* d = definitions_.see(t, depth))
    return "USE " + d->name + " inside the definition of " + d->name + " (DEF at line " + std::to_string(d->line) +
           "): a node cannot hold itself";
  if (const OpenPrototypes::Prototype* p = prototypes_.see(t, depth))
    return p->name + " { } inside the definition of PROTO " + p->name + " (at line " + std::to_string(p->line) +
           "): a prototype cannot hold itself";
  if (std::string step = counterSteps_.see(t, depth); !step.empty()) return step;
  return images_.see(t);
}

}  // namespace figment::viewer
