#include "viewer/SceneTextCheck.h"

#include <Inventor/SoInput.h>
#include <Inventor/lists/SbStringList.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string_view>
#include <vector>

namespace figment::viewer {

namespace {

namespace fs = std::filesystem;

// The text's tokens as far as nesting and File names go: words, quoted strings, and the
// braces and brackets that open and close a level. Outside strings '#' starts a comment
// (the header line is one) and commas separate values as spaces do. A word is a view into
// the text (a volume file is thousands of numbers; none is copied); a string is unescaped.
struct Token {
  enum Kind { kWord, kString, kOpen, kClose, kEnd };
  Kind kind = kEnd;
  std::string_view word;
  std::string string;
  int line = 1;
  std::string_view text() const { return kind == kString ? std::string_view(string) : word; }
};

class Tokenizer {
 public:
  explicit Tokenizer(const std::string& text) : text_(text) {}

  Token next() {
    skipSpaceAndComments();
    Token token;
    token.line = line_;
    if (at_ >= text_.size()) return token;
    const char c = text_[at_];
    if (c == '{' || c == '[' || c == '}' || c == ']') {
      token.word = std::string_view(text_).substr(at_++, 1);
      token.kind = c == '{' || c == '[' ? Token::kOpen : Token::kClose;
    } else if (c == '"') {
      token.kind = Token::kString;
      token.string = quoted();
    } else {
      token.kind = Token::kWord;
      const size_t start = at_;
      while (at_ < text_.size() && !separates(text_[at_])) ++at_;
      token.word = std::string_view(text_).substr(start, at_ - start);
    }
    return token;
  }

 private:
  // Spaces and the characters that end a word: a table, as each character of an included
  // volume file (tens of kilobytes of numbers) is looked at here. Not '\0': a NUL byte taken
  // for a separator that skipSpaceAndComments() does not skip made next() return empty words
  // forever (a scene with a NUL byte hung figment-view; found by tests/fuzz/fuzz_scene).
  static bool separates(char c) {
    static const std::array<bool, 256> table = [] {
      std::array<bool, 256> t{};
      for (int i = 1; i < 256; ++i) t[i] = std::isspace(i) || std::strchr("{}[]\",#", i) != nullptr;
      return t;
    }();
    return table[static_cast<unsigned char>(c)];
  }

  void skipSpaceAndComments() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '#') {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
        line_ += c == '\n';
        ++at_;
      } else {
        return;
      }
    }
  }

  // The string from its opening quote to its closing one; a backslash keeps the next
  // character (\" is a quote in the string, not its end).
  std::string quoted() {
    std::string out;
    for (++at_; at_ < text_.size() && text_[at_] != '"'; ++at_) {
      if (text_[at_] == '\\' && at_ + 1 < text_.size()) ++at_;
      line_ += text_[at_] == '\n';
      out += text_[at_];
    }
    ++at_;
    return out;
  }

  const std::string& text_;
  size_t at_ = 0;
  int line_ = 1;
};

// "" for text Coin reads as ASCII: a header line ("#Inventor V2.1 ascii", "#VRML V2.0 utf8")
// that does not say binary; Coin checks the header itself. Anything else is refused, with what
// it is and what to do, since its nesting and includes cannot be checked from its bytes: Coin
// decompresses gzip and bzip2 before reading (a 2.5 KB gzip of 100,000 nested Separators
// crashed figment-view), reads binary Inventor without a bound on nesting, and takes a file
// without a header that begins "MM" for 3D Studio, whose reader loops forever on a damaged one
// (fuzz_scene: 9 bytes hung figment-view).
std::string notAsciiScene(const std::string& text) {
  if (text.rfind("\x1f\x8b", 0) == 0) return "a gzip-compressed file: decompress it first";
  if (text.rfind("BZh", 0) == 0) return "a bzip2-compressed file: decompress it first";
  if (text.rfind("MM", 0) == 0)
    return "a 3D Studio file (Coin's reader may never finish a damaged one): read the model through a MeshFile";
  if (text.rfind('#', 0) != 0) return "no Inventor or VRML header line (such as \"#Inventor V2.1 ascii\")";
  if (text.substr(0, text.find('\n')).find("binary") != std::string::npos)
    return "a binary Inventor file: write it as ASCII first";
  return "";
}

// The DEF names whose node bodies are open at a point of the text. A USE of one of them
// puts a node inside its own definition: Coin makes it its own child or field value (a
// cycle), and when the inner node's read then fails, destroying it unrefs the outer node
// Coin is still reading, which frees it under the reader (found by fuzz_scene: a comment
// that swallowed a Mannequin's closing brace put `MannequinSkin { mannequin USE Model }`
// inside `DEF Model Mannequin`).
class OpenDefinitions {
 public:
  struct Definition {
    std::string name;
    int line = 0;   // of its DEF
    int depth = 0;  // of its body
  };

  // Takes every token in turn, with the nesting depth after it. Returns the open
  // definition a USE names, if any.
  const Definition* see(const Token& t, int depth) {
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

 private:
  enum class Expect { kNothing, kDefName, kType, kBody, kUseName };
  Expect expect_ = Expect::kNothing;
  std::string pending_;
  int pendingLine_ = 0;
  std::vector<Definition> open_;               // outermost first
  std::map<std::string, int, std::less<>> latest_;  // each name's last DEF line: a USE means that one
};

// The field that names the file a node of `type` includes, "" for other nodes: File's name,
// and an Inline's url, whose first entry Coin reads as a local file the way File does (a
// scene inlining itself crashed figment-view, one inlining /dev/zero hung it).
std::string_view includeField(std::string_view type) {
  if (type == "File" || type == "SoFile") return "name";
  if (type == "VRMLInline" || type == "SoVRMLInline" || type == "Inline") return "url";
  return {};
}

// The first URL of each EXTERNPROTO (VRML97: `EXTERNPROTO Name [ interface ] "url"`, or a list
// `[ "url", ... ]`), which Coin's fetch reads as a file the way it reads a File (a scene whose
// EXTERNPROTO named itself crashed figment-view, one naming /dev/zero hung it).
class ExternProtoUrls {
 public:
  // Takes every token in turn, with the nesting depth after it. Returns the EXTERNPROTO's name
  // when the token is its first URL, else null.
  const std::string* see(const Token& t, int depth) {
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

 private:
  enum class Stage { kNone, kName, kInterface, kInInterface, kUrl, kFirstOfList };
  Stage stage_ = Stage::kNone;
  std::string name_;
  int interfaceDepth_ = 0;
};

class Checker {
 public:
  explicit Checker(const fs::path& scene) : scene_(scene) {}

  std::string run() {
    checkFile(scene_, 0, nullptr);
    return error_;
  }

 private:
  struct OpenFile {
    fs::path asFound;    // its folder is where SoInput looks (SoInput::addDirectoryFirst)
    fs::path canonical;  // what a cycle is found by
  };

  // A node that includes a file (File, VRMLInline): its type, the field naming the file, and
  // the depth of its body.
  struct Includer {
    std::string_view type, field;
    int depth = 0;
  };

  // Where an including node names a file: the file it lies in, its line and how it reads.
  struct Inclusion {
    const fs::path& from;
    int line;
    const std::string& file;  // File { name "..." }, VRMLInline { url "..." }
  };

  // Checks `file`, whose top level lies `base` levels deep, included `by` an including node (null
  // for the scene). False after an error.
  bool checkFile(const fs::path& file, int base, const Inclusion* by) {
    std::ifstream in(file, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (const std::string what = notAsciiScene(text); !what.empty()) {
      if (by) return fail(by->from, by->line, by->file + " names " + what);
      error_ = what;
      return false;
    }
    std::error_code ec;
    chain_.push_back({file, fs::weakly_canonical(file, ec)});
    Tokenizer tokens(text);
    std::vector<Includer> includers;  // the bodies of including nodes open now, innermost last
    std::string_view pendingType;     // an including node's type, its body to open next
    int depth = 0;
    bool expectName = false, expectFirstOfList = false;
    OpenDefinitions definitions;
    ExternProtoUrls externProtos;
    for (Token t = tokens.next(); t.kind != Token::kEnd; t = tokens.next()) {
      if ((expectName || expectFirstOfList) &&
          (t.kind == Token::kString || (t.kind == Token::kWord && t.word != "="))) {
        const std::string name(t.text());
        const Includer& node = includers.back();
        const std::string what = std::string(node.type) + " { " + std::string(node.field) + " \"" + name + "\" }";
        if (!include(what, name, t.line, file, base + depth)) return false;
      } else if (t.kind == Token::kOpen) {
        if (base + ++depth > kMaxNestingDepth)
          return fail(file, t.line,
                      "nesting depth " + std::to_string(base + depth) + " is more than " +
                          std::to_string(kMaxNestingDepth));
        if (!pendingType.empty()) includers.push_back({pendingType, includeField(pendingType), depth});
      } else if (t.kind == Token::kClose) {
        if (!includers.empty() && includers.back().depth == depth) includers.pop_back();
        depth = std::max(depth - 1, 0);  // an unmatched close is Coin's syntax error to report
      }
      if (const OpenDefinitions::Definition* d = definitions.see(t, depth))
        return fail(file, t.line,
                    "USE " + d->name + " inside the definition of " + d->name + " (DEF at line " +
                        std::to_string(d->line) + "): a node cannot hold itself");
      if (const std::string* proto = externProtos.see(t, depth)) {
        // Coin's fetch reads the file named before any "#ProtoName".
        const std::string url(t.text());
        const size_t hash = url.find('#');
        const std::string what = "EXTERNPROTO " + *proto + " \"" + url + "\"";
        if (!include(what, hash != std::string::npos && hash >= 1 ? url.substr(0, hash) : url, t.line, file,
                     base + depth))
          return false;
      }
      expectFirstOfList = expectName && t.kind == Token::kOpen && t.word == "[";  // url [ "a.wrl" ... ]
      expectName = t.kind == Token::kWord && !includers.empty() && includers.back().depth == depth &&
                   t.word == includers.back().field;
      pendingType = t.kind == Token::kWord && !includeField(t.word).empty() ? t.word : std::string_view();
    }
    chain_.pop_back();
    return true;
  }

  // The file `name` that `file` (the text naming it: File { name "a.iv" }) names at `line` of
  // `from`, its contents `depth` levels deep.
  bool include(const std::string& file, const std::string& name, int line, const fs::path& from, int depth) {
    if (name.empty()) return true;  // Coin warns and reads nothing
    const int includeDepth = static_cast<int>(chain_.size());
    if (includeDepth > kMaxIncludeDepth)
      return fail(from, line,
                  file + " would be " + std::to_string(includeDepth) + " includes deep, more than " +
                      std::to_string(kMaxIncludeDepth));
    if (++includes_ > kMaxIncludes)
      return fail(from, line, file + " is include " + std::to_string(includes_) + ", more than " +
                                  std::to_string(kMaxIncludes) + " in all");
    const fs::path found = resolve(name);
    if (found.empty()) return fail(from, line, file + " not found");
    std::error_code ec;
    if (!fs::is_regular_file(found, ec)) return fail(from, line, file + " is not a regular file");
    const fs::path canonical = fs::weakly_canonical(found, ec);
    for (const OpenFile& open : chain_)
      if (open.canonical == canonical)
        return fail(from, line, file + " includes a file already being read: " + chainText(found));
    if (!std::ifstream(found)) return fail(from, line, file + " cannot be read");
    const Inclusion by{from, line, file};
    return checkFile(found, depth, &by);
  }

  // Where SoInput::findFile finds `name`: as given (absolute, or from the working
  // directory), then in the folders of the files being read, innermost first (SoInput
  // adds each one's folder first while reading it), then along SoInput's directories.
  // Folders are passed over, as SoInput does; "" when nowhere.
  fs::path resolve(const std::string& name) const {
    const fs::path given(name);
    std::vector<fs::path> candidates{given};
    if (given.is_relative()) {
      for (auto open = chain_.rbegin(); open != chain_.rend(); ++open)
        candidates.push_back(open->asFound.parent_path() / given);
      const SbStringList& dirs = SoInput::getDirectories();
      for (int i = 0; i < dirs.getLength(); ++i) candidates.push_back(fs::path(dirs[i]->getString()) / given);
    }
    for (const fs::path& candidate : candidates) {
      std::error_code ec;
      const fs::file_status status = fs::status(candidate, ec);
      if (fs::exists(status) && !fs::is_directory(status)) return candidate;
    }
    return {};
  }

  // "a.iv -> b.iv -> a.iv": the files being read, then `next`.
  std::string chainText(const fs::path& next) const {
    std::string out;
    for (const OpenFile& open : chain_) out += open.asFound.filename().string() + " -> ";
    return out + next.filename().string();
  }

  // One line in CoinMessages' form: the file named when it is not the scene.
  bool fail(const fs::path& file, int line, const std::string& what) {
    error_ = "line " + std::to_string(line) + ": " + what;
    if (file != scene_) error_ += " (in " + file.string() + ")";
    return false;
  }

  fs::path scene_;
  std::vector<OpenFile> chain_;  // the files being read, the scene first
  int includes_ = 0;
  std::string error_;
};

}  // namespace

std::string checkSceneText(const std::string& path) { return Checker(path).run(); }

}  // namespace figment::viewer
