#include "io/AssimpHazards.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

namespace figment {

namespace {

// PLY headers are a few hundred bytes; one this long without its end is no PLY file we read.
constexpr std::streamsize kPlyHeaderBytes = 64 * 1024;

std::string lowered(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
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

// The header's lines, "ply" to "end_header", as assimp 5.2 reads them without looping: printable
// text, each line a keyword of the format. "" when they are, else what is wrong.
std::string plyHeaderProblem(const std::string& head) {
  static constexpr std::array<std::string_view, 6> kKeywords = {"format", "comment", "obj_info",
                                                                "element", "property", "end_header"};
  std::istringstream lines(head);
  std::string line;
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
  }
  return "PLY header without end_header in its first 64 KiB";
}

}  // namespace

std::string assimpHazard(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(static_cast<size_t>(kPlyHeaderBytes), '\0');
  in.read(head.data(), kPlyHeaderBytes);
  head.resize(static_cast<size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  if (!looksLikePly(path, head)) return "";
  const std::string problem = plyHeaderProblem(head);
  return problem.empty() ? "" : problem + " (assimp 5.2 may never finish reading it)";
}

}  // namespace figment
