// docs/authoring.md against the node kit itself, so the page cannot drift from the code:
// every node and engine class in FIGMENT's library has a section there whose table
// lists exactly its fields, each with Coin's own type name and default value (as Coin
// writes it), and its example, scenes/examples/<Class>.iv, appears in the page word for
// word.
#include <Inventor/SbString.h>
#include <Inventor/SoType.h>
#include <Inventor/engines/SoEngine.h>
#include <Inventor/engines/SoEngineOutput.h>
#include <Inventor/engines/SoOutputData.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/fields/SoFieldData.h>
#include <Inventor/lists/SoTypeList.h>
#include <Inventor/nodes/SoNode.h>
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "nodes/Init.h"
#include "support/SceneText.h"

namespace fs = std::filesystem;

namespace {

using figment::test::readText;

const fs::path kSource = FIGMENT_SOURCE_DIR;

// Runs of white space as one space, none at either end: Coin writes long values over
// several lines, a table on one.
std::string squeezed(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool space = c == ' ' || c == '\n' || c == '\t' || c == '\r';
    if (space) {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// `text` without one pair of surrounding backticks.
std::string unquoted(std::string text) {
  text = squeezed(text);
  if (text.size() >= 2 && text.front() == '`' && text.back() == '`') text = text.substr(1, text.size() - 2);
  return squeezed(text);
}

struct DocumentedField {
  std::string type, defaultValue;
};

// Each "### `Class`" section's table rows: | `field` | type | `default` | unit | meaning |.
std::map<std::string, std::map<std::string, DocumentedField>> documentedFields(const std::string& page) {
  std::map<std::string, std::map<std::string, DocumentedField>> sections;
  std::istringstream lines(page);
  std::string line, section;
  while (std::getline(lines, line)) {
    if (line.rfind("### ", 0) == 0) {
      section = unquoted(line.substr(4));
      sections[section];
      continue;
    }
    if (line.rfind("## ", 0) == 0) section.clear();
    if (section.empty() || line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream row(line.substr(1));
    while (std::getline(row, cell, '|')) cells.push_back(cell);
    if (cells.size() < 5) continue;
    sections[section][unquoted(cells[0])] = DocumentedField{squeezed(cells[1]), unquoted(cells[2])};
  }
  return sections;
}

// The node and engine classes FIGMENT's library adds: those Coin can make whose maker
// lives in libfigment_nodes (abstract bases such as CollisionVolumeNode never appear in
// a file, so they have no section).
std::vector<SoType> figmentClasses() {
  figment::init();
  std::vector<SoType> classes;
  for (SoType base : {SoNode::getClassTypeId(), SoEngine::getClassTypeId()}) {
    SoTypeList all;
    SoType::getAllDerivedFrom(base, all);
    for (int i = 0; i < all.getLength(); ++i) {
      const SoType type = all[i];
      if (!type.canCreateInstance()) continue;
      Dl_info where{};
      if (!dladdr(reinterpret_cast<void*>(type.getInstantiationMethod()), &where) || !where.dli_fname) continue;
      if (std::string(where.dli_fname).find("libfigment_nodes") != std::string::npos) classes.push_back(type);
    }
  }
  return classes;
}

// The fields of a fresh instance, by name: Coin's type name (SFDouble) and the default
// as Coin writes it; an engine's outputs as type "output" with an empty default.
std::map<std::string, DocumentedField> actualFields(SoType type) {
  std::map<std::string, DocumentedField> fields;
  auto* container = static_cast<SoFieldContainer*>(type.createInstance());
  container->ref();
  const SoFieldData* data = container->getFieldData();
  for (int i = 0; data && i < data->getNumFields(); ++i) {
    SoField* field = data->getField(container, i);
    SbString value;
    field->get(value);
    fields[data->getFieldName(i).getString()] =
        DocumentedField{field->getTypeId().getName().getString(), squeezed(value.getString())};
  }
  if (type.isDerivedFrom(SoEngine::getClassTypeId())) {
    auto* engine = static_cast<SoEngine*>(container);
    const SoEngineOutputData* outputs = engine->getOutputData();
    for (int i = 0; outputs && i < outputs->getNumOutputs(); ++i)
      fields[outputs->getOutputName(i).getString()] = DocumentedField{"output", ""};
  }
  container->unref();
  return fields;
}

// Whether the page's default says what Coin writes: word for word, except that numbers
// need only agree to 6 digits (the page says 0.04 where Coin writes the float as
// 0.039999999).
bool sameDefault(const std::string& documented, const std::string& written) {
  std::istringstream a(documented), b(written);
  std::string x, y;
  while (true) {
    const bool moreA = static_cast<bool>(a >> x), moreB = static_cast<bool>(b >> y);
    if (moreA != moreB) return false;
    if (!moreA) return true;
    if (x == y) continue;
    char* endX = nullptr;
    char* endY = nullptr;
    const double u = std::strtod(x.c_str(), &endX), v = std::strtod(y.c_str(), &endY);
    if (*endX || *endY || endX == x.c_str() || endY == y.c_str()) return false;
    if (std::abs(u - v) > 1e-6 * std::max(std::abs(u), std::abs(v))) return false;
  }
}

TEST(AuthoringDoc, ComparesDefaultsAsNumbersToSixDigits) {
  EXPECT_TRUE(sameDefault("0.04", "0.039999999"));
  EXPECT_TRUE(sameDefault("0 -9.81 0", "0 -9.8100004 0"));
  EXPECT_TRUE(sameDefault("[ ]", "[ ]"));
  EXPECT_FALSE(sameDefault("0.05", "0.039999999"));
  EXPECT_FALSE(sameDefault("0 -9.81", "0 -9.8100004 0"));
  EXPECT_FALSE(sameDefault("HEUN", "IMPLICIT"));
  EXPECT_FALSE(sameDefault("1e6", "1e6x"));
}

TEST(AuthoringDoc, FindsTheNodeKitsClasses) {
  const std::vector<SoType> classes = figmentClasses();
  std::vector<std::string> names;
  for (SoType type : classes) names.emplace_back(type.getName().getString());
  for (const char* expected : {"MeshFile", "ClothEngine", "ClothingLayer", "Mannequin", "CapsuleVolume"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
}

TEST(AuthoringDoc, DocumentsEveryFieldWithItsTypeAndDefault) {
  const auto documented = documentedFields(readText(kSource / "docs/authoring.md"));
  for (SoType type : figmentClasses()) {
    const std::string name = type.getName().getString();
    const auto section = documented.find(name);
    if (section == documented.end()) {
      ADD_FAILURE() << "docs/authoring.md has no section \"### `" << name << "`\"";
      continue;
    }
    const auto actual = actualFields(type);
    for (const auto& [field, value] : actual) {
      const auto row = section->second.find(field);
      const std::string expectedRow = "| `" + field + "` | " + value.type + " | " +
                                      (value.type == "output" ? "—" : "`" + value.defaultValue + "`") + " | | |";
      if (row == section->second.end()) {
        ADD_FAILURE() << name << "." << field << " is not in its table; its row begins\n" << expectedRow;
        continue;
      }
      EXPECT_EQ(row->second.type, value.type) << name << "." << field << ": " << expectedRow;
      if (value.type != "output") {
        EXPECT_TRUE(sameDefault(row->second.defaultValue, value.defaultValue))
            << name << "." << field << ": the page says `" << row->second.defaultValue << "`, Coin writes `"
            << value.defaultValue << "`";
      }
    }
    for (const auto& [field, row] : section->second)
      EXPECT_TRUE(actual.count(field)) << "docs/authoring.md documents " << name << "." << field
                                       << ", which the class does not have";
  }
}

TEST(AuthoringDoc, ShowsEachClassesExampleSceneWordForWord) {
  const std::string page = readText(kSource / "docs/authoring.md");
  for (SoType type : figmentClasses()) {
    const fs::path example = kSource / "scenes/examples" / (std::string(type.getName().getString()) + ".iv");
    ASSERT_TRUE(fs::exists(example)) << example << ": one example per class";
    EXPECT_NE(page.find(readText(example)), std::string::npos)
        << "docs/authoring.md does not quote " << example << " as it is";
  }
}

}  // namespace
