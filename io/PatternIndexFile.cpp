#include "io/PatternIndexFile.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace figment {

namespace {

// entry[key] as a positive number of metres; throws naming the key.
double metres(const nlohmann::json& entry, const char* key, const std::string& where) {
  const auto found = entry.find(key);
  if (found == entry.end() || !found->is_number() || !(found->get<double>() > 0))
    throw std::runtime_error(where + ": " + key + " is not a positive number (m)");
  return found->get<double>();
}

std::string text(const nlohmann::json& entry, const char* key, const std::string& where) {
  const auto found = entry.find(key);
  if (found == entry.end()) throw std::runtime_error(where + ": no \"" + key + "\"");
  if (found->is_number_integer()) return std::to_string(found->get<long long>());
  if (!found->is_string() || found->get<std::string>().empty())
    throw std::runtime_error(where + ": \"" + key + "\" is not a name");
  return found->get<std::string>();
}

}  // namespace

std::vector<PatternIndexEntry> readPatternIndex(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be opened");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& error) {
    throw std::runtime_error(path + ": not JSON (byte " + std::to_string(error.byte) + ")");
  }
  if (!json.is_object() || !json.contains("patterns") || !json["patterns"].is_array())
    throw std::runtime_error(path + ": no \"patterns\" list");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::vector<PatternIndexEntry> entries;
  for (size_t i = 0; i < json["patterns"].size(); ++i) {
    const nlohmann::json& item = json["patterns"][i];
    const std::string where = path + ": patterns[" + std::to_string(i) + "]";
    if (!item.is_object()) throw std::runtime_error(where + ": not an object");
    PatternIndexEntry entry;
    entry.style = text(item, "style", where);
    const std::string sex = text(item, "sex", where);
    if (sex != "female" && sex != "male") throw std::runtime_error(where + ": sex " + sex + " is not female or male");
    entry.sex = sex == "male" ? Sex::Male : Sex::Female;
    entry.size = text(item, "size", where);
    entry.number = text(item, "number", where);
    entry.body = {entry.sex,
                  entry.size,
                  entry.number,
                  metres(item, "stature", where),
                  metres(item, "bust", where),
                  metres(item, "waist", where),
                  metres(item, "hips", where)};
    entry.file = (folder / text(item, "file", where)).string();
    entries.push_back(std::move(entry));
  }
  return entries;
}

}  // namespace figment
