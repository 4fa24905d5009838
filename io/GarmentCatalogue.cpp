#include "io/GarmentCatalogue.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "io/PatternFile.h"
#include "io/SizeChartFile.h"
#include "sim/cloth/MaterialPresets.h"
#include "sim/fit/FitRegion.h"

namespace figment {

namespace {

// A file's lines without comments or blanks, each with "<path>:<line>" for messages.
struct Line {
  std::string where;
  std::vector<std::string> words;
};

std::vector<Line> readLines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be opened");
  std::vector<Line> lines;
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    std::istringstream fields(text.substr(0, text.find('#')));
    Line line{path + ":" + std::to_string(number), {}};
    for (std::string word; fields >> word;) line.words.push_back(word);
    if (!line.words.empty()) lines.push_back(std::move(line));
  }
  return lines;
}

std::string besides(const std::string& indexPath, const std::string& name) {
  return (std::filesystem::path(indexPath).parent_path() / name).string();
}

// The chart the index names: its "chart FILE" line.
std::string chartPathOf(const std::string& indexPath) {
  for (const Line& line : readLines(indexPath))
    if (line.words[0] == "chart" && line.words.size() == 2) return besides(indexPath, line.words[1]);
  throw std::runtime_error(indexPath + ": no \"chart FILE\" line");
}

// The pattern index the index names (its "patterns FILE" line), read; none without one.
std::vector<PatternIndexEntry> patternsOf(const std::string& indexPath) {
  for (const Line& line : readLines(indexPath))
    if (line.words[0] == "patterns" && line.words.size() == 2) {
      try {
        return readPatternIndex(besides(indexPath, line.words[1]));
      } catch (const std::exception& error) {
        throw std::runtime_error(line.where + ": " + error.what());
      }
    }
  return {};
}

bool isColour(const std::string& text) {
  return text.size() == 6 && std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isxdigit(c); });
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& word : words) out += (out.empty() ? "" : ", ") + word;
  return out;
}

// One "female|male SIZES..." line into `style`, each size checked against the chart.
void readSizes(const Line& line, const SizeChart& chart, CatalogueStyle& style) {
  const Sex sex = line.words[0] == "male" ? Sex::Male : Sex::Female;
  if (std::find(style.sexes.begin(), style.sexes.end(), sex) != style.sexes.end())
    throw std::runtime_error(line.where + ": " + line.words[0] + " sizes given twice");
  style.sexes.push_back(sex);
  std::vector<std::string>& sizes = sex == Sex::Male ? style.male : style.female;
  for (size_t i = 1; i < line.words.size(); ++i) {
    const int index = chart.find(sex, line.words[i]);
    if (index < 0)
      throw std::runtime_error(line.where + ": the size chart has no " + line.words[0] + " size " + line.words[i]);
    sizes.push_back(chart.sizes(sex)[index].name);
  }
  if (sizes.empty()) throw std::runtime_error(line.where + ": no sizes");
}

// A "regions NAME, NAME..." line's names (a name may have spaces: "upper arms").
std::vector<std::string> readRegions(const Line& line) {
  std::string rest;
  for (size_t i = 1; i < line.words.size(); ++i) rest += (i > 1 ? " " : "") + line.words[i];
  std::vector<std::string> regions;
  std::istringstream in(rest);
  for (std::string name; std::getline(in, name, ',');) {
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    const std::vector<std::string>& known = fitRegionNames();
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw std::runtime_error(line.where + ": region '" + name + "' is not one of " + joined(known));
    regions.push_back(name);
  }
  return regions;
}

// A pattern style's sizes, each found in the pattern index (`where`: its sex's line).
void findPatterns(const std::vector<PatternIndexEntry>& index, const std::map<Sex, std::string>& where,
                  CatalogueStyle& style) {
  for (const Sex sex : style.sexes)
    for (const std::string& size : style.sizes(sex)) {
      const auto entry = std::find_if(index.begin(), index.end(), [&](const PatternIndexEntry& e) {
        return e.style == style.pattern && e.sex == sex && e.size == size;
      });
      if (entry == index.end())
        throw std::runtime_error(where.at(sex) + ": the pattern index has no " + sexName(sex) + " " + style.pattern +
                                 " in size " + size);
      style.patterns.push_back(*entry);
    }
}

// The pattern index's style names, for messages.
std::string patternStyleNames(const std::vector<PatternIndexEntry>& index) {
  std::vector<std::string> names;
  for (const PatternIndexEntry& entry : index)
    if (std::find(names.begin(), names.end(), entry.style) == names.end()) names.push_back(entry.style);
  return joined(names);
}

// Where a style file said what (file:line), for the checks after its last line.
struct StyleLines {
  std::string style, fabric, regions, about;
  std::map<Sex, std::string> sizes;
};

// A pattern style's own name, cloth and regions and its sizes' patterns; a generator style's
// cloth and regions its generator's. Throws naming the line.
void completeStyle(const std::string& path, const StyleLines& where, const std::vector<PatternIndexEntry>& index,
                   CatalogueStyle& style) {
  const GarmentStyle* generator = findStyle(style.name);
  if (style.sewn()) {
    // Its own name, so "tshirt:M" always means the generator's T-shirt.
    if (generator)
      throw std::runtime_error(where.style + ": style " + style.name +
                               " is a generator's; a pattern style needs a name of its own");
    if (style.fabric.empty()) throw std::runtime_error(path + ": no \"fabric PRESET\" line (a pattern style's cloth)");
    if (style.regions.empty())
      throw std::runtime_error(path + ": no \"regions NAME, ...\" line (where a pattern style's fit is told)");
    if (style.about.empty())
      throw std::runtime_error(path + ": no \"about TEXT\" line (a pattern style's line for shoppers)");
    findPatterns(index, where.sizes, style);
  } else {
    if (!generator)
      throw std::runtime_error(where.style + ": style " + style.name + " is not one of " + styleNames() +
                               " (or give \"patterns STYLE\" for a pattern style)");
    // A generator cuts for its own cloth and regions (sim/garment/GarmentStyle.h).
    if (!where.fabric.empty()) throw std::runtime_error(where.fabric + ": a generator style's fabric is its own");
    if (!where.regions.empty()) throw std::runtime_error(where.regions + ": a generator style's regions are its own");
    if (!where.about.empty()) throw std::runtime_error(where.about + ": a generator style's about is its own");
    style.about = generator->about;
    style.fabric = generator->fabric;
    style.regions = generator->regions;
  }
}

CatalogueStyle readStyle(const std::string& path, const SizeChart& chart, const std::vector<PatternIndexEntry>& index) {
  CatalogueStyle style;
  StyleLines where;
  for (const Line& line : readLines(path)) {
    const std::string& key = line.words[0];
    if (key == "style" && line.words.size() == 2) {
      style.name = line.words[1], where.style = line.where;
    } else if (key == "patterns" && line.words.size() == 2) {
      if (index.empty())
        throw std::runtime_error(line.where + ": patterns " + line.words[1] +
                                 ", but the catalogue's index has no \"patterns FILE\" line");
      if (std::none_of(index.begin(), index.end(),
                       [&](const PatternIndexEntry& e) { return e.style == line.words[1]; }))
        throw std::runtime_error(line.where + ": the pattern index has no style " + line.words[1] + " (" +
                                 patternStyleNames(index) + ")");
      style.pattern = line.words[1];
    } else if (key == "fabric" && line.words.size() == 2) {
      if (!materialPreset(line.words[1]))
        throw std::runtime_error(line.where + ": fabric " + line.words[1] + " is not one of " +
                                 joined(materialPresetNames()));
      style.fabric = line.words[1], where.fabric = line.where;
    } else if (key == "about" && line.words.size() >= 2) {
      for (size_t i = 1; i < line.words.size(); ++i) style.about += (i > 1 ? " " : "") + line.words[i];
      where.about = line.where;
    } else if (key == "regions" && line.words.size() >= 2) {
      style.regions = readRegions(line), where.regions = line.where;
    } else if (key == "female" || key == "male") {
      readSizes(line, chart, style);
      where.sizes[style.sexes.back()] = line.where;
    } else if (key == "colours") {
      for (size_t i = 1; i < line.words.size(); ++i) {
        if (!isColour(line.words[i]))
          throw std::runtime_error(line.where + ": colour " + line.words[i] + " is not six hex digits (rrggbb)");
        style.colours.push_back(lower(line.words[i]));
      }
    } else {
      throw std::runtime_error(line.where + ": '" + key +
                               "' is not style, patterns, fabric, regions, female, male or colours");
    }
  }
  if (style.name.empty()) throw std::runtime_error(path + ": no \"style NAME\" line");
  if (style.sexes.empty()) throw std::runtime_error(path + ": no sizes (\"female SIZES...\" or \"male SIZES...\")");
  if (style.colours.empty()) throw std::runtime_error(path + ": no \"colours RRGGBB...\" line");
  completeStyle(path, where, index, style);
  return style;
}

std::vector<std::string> split(const std::string& name) {
  std::vector<std::string> parts;
  std::string part;
  for (std::istringstream in(name); std::getline(in, part, ':');) parts.push_back(part);
  if (!name.empty() && name.back() == ':') parts.push_back("");
  return parts;
}

}  // namespace

const PatternIndexEntry* CatalogueStyle::patternOf(Sex sex, const std::string& size) const {
  for (const PatternIndexEntry& entry : patterns)
    if (entry.sex == sex && entry.size == size) return &entry;
  return nullptr;
}

std::string CatalogueItem::name() const {
  return styleName + ":" + sizeName + ":" + colour;
}

GarmentCatalogue::GarmentCatalogue(const std::string& indexPath)
    : chart_(readSizeChart(chartPathOf(indexPath))), patterns_(patternsOf(indexPath)) {
  for (const Line& line : readLines(indexPath)) {
    if ((line.words[0] == "chart" || line.words[0] == "patterns") && line.words.size() == 2) continue;
    if (line.words[0] != "style" || line.words.size() != 2)
      throw std::runtime_error(line.where + ": expected \"chart FILE\", \"patterns FILE\" or \"style FILE\"");
    CatalogueStyle style = readStyle(besides(indexPath, line.words[1]), chart_, patterns_);
    if (this->style(style.name)) throw std::runtime_error(line.where + ": style " + style.name + " listed twice");
    styles_.push_back(std::move(style));
  }
  if (styles_.empty()) throw std::runtime_error(indexPath + ": no \"style FILE\" line");
}

const CatalogueStyle* GarmentCatalogue::style(const std::string& name) const {
  for (const CatalogueStyle& style : styles_)
    if (style.name == name) return &style;
  return nullptr;
}

std::string GarmentCatalogue::styleNames() const {
  std::vector<std::string> names;
  for (const CatalogueStyle& style : styles_) names.push_back(style.name);
  return joined(names);
}

CatalogueItem GarmentCatalogue::resolve(const std::string& name) const {
  return resolveIn(name, nullptr);
}

CatalogueItem GarmentCatalogue::resolve(const std::string& name, Sex sex) const {
  return resolveIn(name, &sex);
}

CatalogueItem GarmentCatalogue::resolveIn(const std::string& name, const Sex* sex) const {
  const std::vector<std::string> parts = split(name);
  if (parts.size() < 2 || parts.size() > 3)
    throw std::invalid_argument("\"" + name + "\" is not style:size[:rrggbb] (styles " + styleNames() + ")");
  const CatalogueStyle* found = style(parts[0]);
  if (!found) throw std::invalid_argument("\"" + name + "\": no style " + parts[0] + " (styles " + styleNames() + ")");
  CatalogueItem item;
  item.styleName = found->name;
  item.style = found->sewn() ? nullptr : findStyle(found->name);
  item.fabric = found->fabric;
  item.regions = found->regions;
  // A letter code in the given sex (else the style's first); a number in whichever sex has it.
  const std::vector<Sex> order = sex ? std::vector<Sex>{*sex} : found->sexes;
  item.size = -1;
  for (const Sex candidate : order) {
    const int index = chart_.find(candidate, parts[1]);
    const bool sold = index >= 0 && std::find(found->sizes(candidate).begin(), found->sizes(candidate).end(),
                                              chart_.sizes(candidate)[index].name) != found->sizes(candidate).end();
    const bool byNumber = index >= 0 && chart_.sizes(candidate)[index].number == parts[1];
    if (sold && (candidate == order.front() || byNumber)) {
      item.sex = candidate, item.size = index, item.sizeName = chart_.sizes(candidate)[index].name;
      break;
    }
  }
  if (item.size < 0) {
    std::string accepted;
    for (const Sex s : found->sexes)
      accepted += (accepted.empty() ? "" : "; ") + std::string(sexName(s)) + " " + joined(found->sizes(s));
    throw std::invalid_argument("\"" + name + "\": no size " + parts[1] + " of " + found->name + " (" + accepted + ")");
  }
  if (const PatternIndexEntry* pattern = found->patternOf(item.sex, item.sizeName)) {
    item.patternFile = pattern->file;
    item.madeForStature = pattern->body.stature;
  }
  item.colour = parts.size() == 3 ? lower(parts[2]) : found->colours.front();
  if (!isColour(item.colour))
    throw std::invalid_argument("\"" + name + "\": colour " + parts[2] + " is not six hex digits (rrggbb)");
  return item;
}

SewnStyle sewnStyle(const CatalogueStyle& style, const SizeChart& chart) {
  SewnStyle sewn;
  sewn.fabric = style.fabric;
  sewn.regions = style.regions;
  for (const PatternIndexEntry& entry : style.patterns)
    if (const int size = chart.find(entry.sex, entry.size); size >= 0)
      sewn.sizes[{entry.sex, size}] = {readPatternFile(entry.file), entry.body.stature};
  return sewn;
}

std::string defaultCataloguePath() {
  return FIGMENT_CATALOGUE_DEFAULT;
}

}  // namespace figment
