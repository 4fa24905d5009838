// nodes/NodeTypes.cpp's list is the node kit: the same classes as nodes/ declares (a class
// left out of the list would never be registered), the same types Coin learns from
// figment::init() (a type registered another way, or a listed one that registers nothing,
// fails), each with its lib<Class>.so link beside the library and its example scene.
#include <Inventor/SoDB.h>
#include <Inventor/SoType.h>
#include <Inventor/engines/SoEngine.h>
#include <Inventor/lists/SoTypeList.h>
#include <Inventor/nodes/SoNode.h>
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "nodes/Init.h"
#include "nodes/NodeTypes.h"

namespace fs = std::filesystem;

namespace {

std::set<std::string> listedNames() {
  std::set<std::string> names;
  for (const figment::NodeType& type : figment::nodeTypes()) names.insert(type.name);
  return names;
}

// The concrete classes nodes/ declares: SO_NODE_HEADER(Name) or SO_ENGINE_HEADER(Name) in a header.
std::set<std::string> declaredNames() {
  const std::regex declaration(R"(SO_(NODE|ENGINE)_HEADER\((\w+)\))");
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(FIGMENT_SOURCE_DIR "/nodes")) {
    if (entry.path().extension() != ".h") continue;
    std::stringstream text;
    text << std::ifstream(entry.path()).rdbuf();
    const std::string source = text.str();
    for (std::sregex_iterator it(source.begin(), source.end(), declaration), end; it != end; ++it)
      names.insert((*it)[2]);
  }
  return names;
}

// The node and engine types Coin knows that can be made (abstract bases left out), by name.
std::set<std::string> creatableTypes() {
  std::set<std::string> names;
  for (SoType base : {SoNode::getClassTypeId(), SoEngine::getClassTypeId()}) {
    SoTypeList types;
    SoType::getAllDerivedFrom(base, types);
    for (int i = 0; i < types.getLength(); ++i)
      if (types[i].canCreateInstance()) names.insert(types[i].getName().getString());
  }
  return names;
}

std::string joined(const std::set<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::set<std::string> minus(const std::set<std::string>& a, const std::set<std::string>& b) {
  std::set<std::string> rest;
  for (const std::string& name : a)
    if (!b.count(name)) rest.insert(name);
  return rest;
}

TEST(NodeTypes, ListsEveryClassNodesDeclaresAndNoOther) {
  const std::set<std::string> declared = declaredNames(), listed = listedNames();
  ASSERT_FALSE(declared.empty());  // the control: the scan finds the declarations
  EXPECT_EQ(minus(declared, listed), std::set<std::string>()) << "declared in nodes/, not in NodeTypes.cpp";
  EXPECT_EQ(minus(listed, declared), std::set<std::string>()) << "in NodeTypes.cpp, declared nowhere in nodes/";
  EXPECT_EQ(listed.size(), figment::nodeTypes().size()) << "a class listed twice";
}

TEST(NodeTypes, AreExactlyTheTypesCoinLearnsFromInit) {
  SoDB::init();
  // Precondition: the kit is not registered yet (ctest runs each test in a process of its own).
  if (SoType::fromName("ClothEngine") != SoType::badType()) GTEST_SKIP() << "the kit was registered before this test";
  const std::set<std::string> before = creatableTypes();
  figment::init();
  const std::set<std::string> learnt = minus(creatableTypes(), before), listed = listedNames();
  EXPECT_EQ(minus(learnt, listed), std::set<std::string>())
      << "registered by figment::init(), not listed: " << joined(learnt);
  EXPECT_EQ(minus(listed, learnt), std::set<std::string>()) << "listed, not registered: " << joined(learnt);
}

TEST(NodeTypes, EachHasItsLibraryLinkAndItsExampleScene) {
  Dl_info library{};
  ASSERT_NE(dladdr(reinterpret_cast<void*>(&figment::init), &library), 0);
  const fs::path folder = fs::path(library.dli_fname).parent_path();
  for (const figment::NodeType& type : figment::nodeTypes()) {
    const std::string name = type.name;
    EXPECT_TRUE(fs::exists(folder / ("lib" + name + ".so"))) << folder / ("lib" + name + ".so");
    EXPECT_TRUE(fs::exists(fs::path(FIGMENT_SOURCE_DIR) / "scenes/examples" / (name + ".iv"))) << name;
  }
}

}  // namespace
