#include "guard/SceneTextCheck.h"

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

#include "guard/SceneTextWatchers.h"
#include "guard/SceneTokens.h"

namespace figment::guard {

namespace {

namespace fs = std::filesystem;

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

// The field that names the file a node of `type` includes, "" for other nodes: File's name,
// and an Inline's url, whose first entry Coin reads as a local file the way File does (a
// scene inlining itself crashed figment-view, one inlining /dev/zero hung it).
std::string_view includeField(std::string_view type) {
  if (type == "File" || type == "SoFile") return "name";
  if (type == "VRMLInline" || type == "SoVRMLInline" || type == "Inline") return "url";
  return {};
}

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
    ReaderHazards hazards(text.size());
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
          return fail(
              file, t.line,
              "nesting depth " + std::to_string(base + depth) + " is more than " + std::to_string(kMaxNestingDepth));
        if (!pendingType.empty()) includers.push_back({pendingType, includeField(pendingType), depth});
      } else if (t.kind == Token::kClose) {
        if (!includers.empty() && includers.back().depth == depth) includers.pop_back();
        depth = std::max(depth - 1, 0);  // an unmatched close is Coin's syntax error to report
      }
      if (const std::string hazard = hazards.see(t, depth); !hazard.empty()) return fail(file, t.line, hazard);
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
      return fail(from, line,
                  file + " is include " + std::to_string(includes_) + ", more than " + std::to_string(kMaxIncludes) +
                      " in all");
    const fs::path found = resolve(name);
    if (found.empty()) return fail(from, line, file + " not found: " + whereLooked(name));
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

  // Where resolve() looked for `name`, in its order, for the line that says it is nowhere:
  // "looked beside scene.iv (/a/scene/folder) and in the working directory (/a/run)".
  std::string whereLooked(const std::string& name) const {
    const fs::path given(name);
    std::error_code ec;
    if (given.is_absolute()) return "no such file";
    std::vector<std::string> places;
    for (auto open = chain_.rbegin(); open != chain_.rend(); ++open) {
      const fs::path folder = fs::absolute(open->asFound, ec).parent_path();
      places.push_back("beside " + open->asFound.filename().string() + " (" + folder.string() + ")");
    }
    places.push_back("in the working directory (" + fs::current_path(ec).string() + ")");
    const SbStringList& dirs = SoInput::getDirectories();
    for (int i = 0; i < dirs.getLength(); ++i)
      if (std::string dir = dirs[i]->getString(); !dir.empty() && dir != ".") places.push_back("in " + dir);
    std::string text = "looked ";
    for (size_t i = 0; i < places.size(); ++i)
      text += (i == 0 ? "" : i + 1 == places.size() ? " and " : ", ") + places[i];
    return text;
  }

  // "a.iv -> b.iv -> a.iv": the files being read, then `next`.
  std::string chainText(const fs::path& next) const {
    std::string out;
    for (const OpenFile& open : chain_) out += open.asFound.filename().string() + " -> ";
    return out + next.filename().string();
  }

  // One line in ReadMessages' form: the file named when it is not the scene.
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

std::string checkSceneText(const std::string& path) {
  return Checker(path).run();
}

}  // namespace figment::guard
