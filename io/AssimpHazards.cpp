#include "io/AssimpHazards.h"

#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string_view>
#include <vector>

namespace figment {

namespace {

// PLY headers are a few hundred bytes; one this long without its end is no PLY file we read.
constexpr std::streamsize kPlyHeaderBytes = 64 * 1024;

std::string lowered(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// A ".ply" name, or text whose first word is "ply": assimp 5.2 picks its PLY reader by name
// and, for a name no reader claims, by that word.
bool looksLikePly(const std::string& path, const std::string& head) {
  if (lowered(std::filesystem::path(path).extension().string()) == ".ply") return true;
  const size_t start = head.find_first_not_of(" \t\r\n");
  return start != std::string::npos && lowered(head.substr(start, 4)).rfind("ply", 0) == 0 &&
         (head.size() == start + 3 || std::isspace(static_cast<unsigned char>(head[start + 3])));
}

// An element count as a PLY header gives it: decimal digits (assimp 5.2 reads the digits a word
// begins with and wraps past 2^32). Shown cut short in an error line.
std::string shownCount(const std::string& word) {
  return word.size() <= 20 ? word : word.substr(0, 20) + "...";
}

// The header's lines, "ply" to "end_header", as assimp 5.2 reads them without looping: printable
// text, each line a keyword of the format, and element counts the file's `bytes` can hold. Each
// element takes at least a byte (a binary property, or an ASCII line's end); assimp 5.2 reads
// every counted element, seeking once for each past the end of the file, so a count far beyond
// the file hung it (fuzz_mesh: "element face 6666...60" in a 332-byte file; a million took 4 s).
// "" when they are, else what is wrong.
std::string plyHeaderProblem(const std::string& head, std::uintmax_t bytes) {
  static constexpr std::array<std::string_view, 6> kKeywords = {"format",  "comment",  "obj_info",
                                                                "element", "property", "end_header"};
  std::istringstream lines(head);
  std::string line;
  std::uintmax_t elements = 0;  // counted so far, every element
  for (int number = 1; std::getline(lines, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    for (const char c : line)
      if ((c < 0x20 || c > 0x7e) && c != '\t')
        return "PLY header line " + std::to_string(number) + " holds a control or non-ASCII byte";
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (number == 1) {
      if (keyword != "ply") return "PLY header does not begin with \"ply\"";
      continue;
    }
    if (keyword == "end_header") return "";
    if (std::find(kKeywords.begin(), kKeywords.end(), keyword) == kKeywords.end())
      return "PLY header line " + std::to_string(number) + " does not begin with a PLY keyword";
    if (keyword != "element") continue;
    std::string name, count;
    words >> name >> count;
    const std::string where = "PLY header line " + std::to_string(number) + ": element " + name + " count \"";
    if (count.empty() || count.size() > 18 || !std::all_of(count.begin(), count.end(), ::isdigit))
      return where + shownCount(count) + "\" is not a whole number";
    elements += std::stoull(count);
    if (elements > bytes)
      return where + count + "\" makes more elements than the file's " + std::to_string(bytes) + " bytes hold";
  }
  return "PLY header without end_header in its first 64 KiB";
}

// ".off", or text starting "off" (any case): assimp 5.2's OFF reader claims it.
bool looksLikeOff(const std::string& path, const std::string& head) {
  return lowered(std::filesystem::path(path).extension().string()) == ".off" || lowered(head.substr(0, 3)) == "off";
}

// The file as assimp 5.2's OFF reader needs it: "OFF", the vertex and face counts, that many
// vertex lines of three numbers and face lines "n i1 ... in" (1 <= n <= 9, every index a
// vertex). Its reader trusts the counts and lines and can write past what it allocated
// otherwise (fuzz_mesh: SEGV). Blank lines and # comments are skipped, as it does.
// "" when the file is so, else what is wrong.
std::string offProblem(const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  std::vector<std::string> words;
  const auto nextLine = [&]() {
    while (std::getline(lines, line)) {
      ++number;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      for (const char c : line)
        if ((c < 0x20 || c > 0x7e) && c != '\t') return false;
      std::istringstream in(line);
      words.assign(std::istream_iterator<std::string>(in), std::istream_iterator<std::string>());
      if (!words.empty() && words[0][0] != '#') return true;
    }
    words.clear();
    return false;
  };
  const auto count = [](const std::string& word, long long& value) {
    return !word.empty() && word.size() < 10 && std::all_of(word.begin(), word.end(), ::isdigit) &&
           ((value = std::stoll(word)), true);
  };
  const auto bad = [&](const std::string& what) { return "OFF file line " + std::to_string(number) + ": " + what; };
  if (!nextLine() || lowered(words[0]) != "off") return "OFF file without its \"OFF\" line";
  if (words.size() == 1 && !nextLine()) return bad("no vertex and face counts");
  const size_t first = words.size() >= 3 && lowered(words[0]) == "off" ? 1 : 0;
  long long vertices = 0, faces = 0;
  if (words.size() < first + 2 || !count(words[first], vertices) || !count(words[first + 1], faces) || vertices < 1 ||
      faces < 1)
    return bad("not the vertex and face counts");
  for (long long v = 0; v < vertices; ++v) {
    if (!nextLine()) return bad("fewer vertices than the " + std::to_string(vertices) + " counted");
    if (words.size() < 3) return bad("a vertex of fewer than 3 numbers");
  }
  for (long long f = 0; f < faces; ++f) {
    if (!nextLine()) return bad("fewer faces than the " + std::to_string(faces) + " counted");
    long long corners = 0, index = 0;
    if (!count(words[0], corners) || corners < 1 || corners > 9 || words.size() < static_cast<size_t>(corners) + 1)
      return bad("not a face of 1 to 9 corners and their indices");
    for (long long c = 1; c <= corners; ++c)
      if (!count(words[c], index) || index >= vertices) return bad("a face index that is not a vertex");
  }
  return "";
}

}  // namespace

std::string assimpHazard(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(static_cast<size_t>(kPlyHeaderBytes), '\0');
  in.read(head.data(), kPlyHeaderBytes);
  head.resize(static_cast<size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  if (looksLikePly(path, head)) {
    std::error_code ec;
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    const std::string problem = plyHeaderProblem(head, ec ? head.size() : bytes);
    return problem.empty() ? "" : problem + " (assimp 5.2 may never finish reading it)";
  }
  if (looksLikeOff(path, head)) {
    // OFF is text: the whole file is read (meshes we read as OFF are small).
    std::string text = head;
    text.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    const std::string problem = offProblem(text);
    return problem.empty() ? "" : problem + " (assimp 5.2 may crash on it)";
  }
  return "";
}

void correctPrimitiveTypes(aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    aiMesh& mesh = *scene.mMeshes[m];
    unsigned types = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const unsigned n = mesh.mFaces[f].mNumIndices;
      types |= n == 1   ? aiPrimitiveType_POINT
               : n == 2 ? aiPrimitiveType_LINE
               : n == 3 ? aiPrimitiveType_TRIANGLE
                        : aiPrimitiveType_POLYGON;
    }
    mesh.mPrimitiveTypes = types;
  }
}

}  // namespace figment
