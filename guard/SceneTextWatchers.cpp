#include "guard/SceneTextWatchers.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <optional>

namespace figment::guard {

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
  if (t.word == "{" && !open_.empty() && !open_.back().body && depth == open_.back().depth + 1 && before.empty()) {
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

// The whole number Coin reads from the start of `word`, and the rest of the word. Coin reads
// an integer's characters while they last and leaves the rest to its next read: `step 0.5`,
// `step 08` and `step 0abc` all set 0 (and raised SIGFPE; found by fuzz_scene). None where
// the word does not start with one ("0x" alone included): Coin's read error to report.
struct LeadingNumber {
  long long value;
  std::string_view rest;
};

std::optional<LeadingNumber> leadingWholeNumber(std::string_view word) {
  const std::string text(word);
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), &end, 0);
  if (end == text.c_str() || errno != 0 || *end == 'x' || *end == 'X') return std::nullopt;
  return LeadingNumber{value, word.substr(static_cast<size_t>(end - text.c_str()))};
}

// Whether `word` begins with the field name `name`: Coin's names end at the first character
// that is not a letter, digit or '_' (`step=X.output` is the field step, connected).
bool startsWithFieldName(std::string_view word, std::string_view name) {
  if (!word.starts_with(name)) return false;
  return word.size() == name.size() ||
         !(std::isalnum(static_cast<unsigned char>(word[name.size()])) || word[name.size()] == '_');
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
  if (expected == Expect::kConnection && t.word.starts_with('=')) return connectedStep();
  if (expected == Expect::kStepValue) return stepValue(t.word);
  if (bodyDepth_ >= 0 && depth == bodyDepth_ && startsWithFieldName(t.word, "step")) {
    if (t.word.size() == 4) {
      expect_ = Expect::kStepValue;
      return "";
    }
    return stepValue(t.word.substr(4));  // `step=X.output`
  }
  if (isCounter(t.word)) pendingType_ = t.word, expect_ = Expect::kBody;
  return "";
}

std::string CounterSteps::stepValue(std::string_view word) {
  if (word.starts_with('=')) return connectedStep();
  const auto number = leadingWholeNumber(word);
  if (!number) return "";          // Coin's read error
  if (number->value % 65536 == 0)  // a short holds 65536 as 0
    return std::string(type_) + " { step " + std::string(word) + " } divides by zero: " +
           (number->rest.empty() ? "" : "Coin reads it as " + std::to_string(number->value) + "; ") +
           "the step must not be 0 (or a multiple of 65536)";
  if (number->rest.starts_with('=')) return connectedStep();  // `step 1=X.output`
  if (number->rest.empty()) expect_ = Expect::kConnection;    // `step 1 = X.output` connects it as well
  return "";
}

std::string CounterSteps::connectedStep() const {
  return std::string(type_) +
         " { step = ... } takes its step from a connection: Coin divides by the step, and a "
         "step of 0 crashes it; give the step as a number";
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
  // A number Coin reads from the start of a longer word (`4.5`) counts as that number: it
  // allocates the image before its read of the rest fails.
  const auto number = t.kind == Token::kWord ? leadingWholeNumber(t.word) : std::nullopt;
  if (!number) {
    wanted_ = 0;  // not an image size after all, or Coin's read error to report
    return "";
  }
  dimensions_.push_back(number->value);
  if (dimensions_.size() < wanted_) return "";
  wanted_ = 0;
  long long pixels = 1;
  std::string size;
  for (size_t i = 0; i + 1 < dimensions_.size(); ++i) {
    const auto read = static_cast<short>(dimensions_[i]);  // as Coin reads it, into a short
    if (read <= 0) return "";                              // Coin refuses or reads an empty image
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

}  // namespace figment::guard
