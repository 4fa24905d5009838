#include "viewer/NodeCatalog.h"

#include <Inventor/engines/SoEngine.h>
#include <Inventor/engines/SoOutputData.h>
#include <Inventor/fields/SoFieldData.h>
#include <Inventor/fields/SoMFEnum.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/lists/SoTypeList.h>
#include <Inventor/nodes/SoNode.h>

#include <algorithm>
#include <set>

namespace figment::viewer {

namespace {

std::set<std::string> namesDerivedFrom(SoType base) {
  SoTypeList types;
  SoType::getAllDerivedFrom(base, types);
  std::set<std::string> names;
  for (int i = 0; i < types.getLength(); ++i) names.insert(types[i].getName().getString());
  return names;
}

// A field's value as one line: an .iv file writes long multiple values over lines.
std::string valueText(SoField& field) {  // SoField::get is not const
  SbString text;
  field.get(text);
  std::string line;
  for (char c : std::string(text.getString())) {
    const char one = (c == '\n' || c == '\r' || c == '\t') ? ' ' : c;
    if (one == ' ' && !line.empty() && line.back() == ' ') continue;
    line += one;
  }
  return line;
}

// " {EULER, SYMPLECTIC, ...}" for an enum field, "" for the others.
std::string enumChoices(const SoField& field) {
  const SoSFEnum* single = field.isOfType(SoSFEnum::getClassTypeId()) ? static_cast<const SoSFEnum*>(&field) : nullptr;
  const SoMFEnum* multiple =
      field.isOfType(SoMFEnum::getClassTypeId()) ? static_cast<const SoMFEnum*>(&field) : nullptr;
  const int count = single ? single->getNumEnums() : multiple ? multiple->getNumEnums() : 0;
  std::string text;
  for (int i = 0; i < count; ++i) {
    SbName name;
    single ? single->getEnum(i, name) : multiple->getEnum(i, name);
    text += i ? ", " : " {";
    text += name.getString();
  }
  return count ? text + "}" : "";
}

// `text` followed by spaces up to `width` characters (and one space at least).
std::string column(const std::string& text, size_t width) {
  return text + std::string(text.size() < width ? width - text.size() : 1, ' ');
}

std::string describe(SoType type) {
  const bool engine = type.isDerivedFrom(SoEngine::getClassTypeId());
  std::string text = std::string(type.getName().getString()) + " (" + (engine ? "engine" : "node") + ", derived from " +
                     type.getParent().getName().getString() + ")\n";
  if (!type.canCreateInstance()) return text + "  abstract: not written in a scene itself\n";
  auto* container = static_cast<SoFieldContainer*>(type.createInstance());
  container->ref();
  const SoFieldData* fields = container->getFieldData();
  for (int i = 0; fields && i < fields->getNumFields(); ++i) {
    SoField* field = fields->getField(container, i);
    text += "  " + column(fields->getFieldName(i).getString(), 21) +
            column(field->getTypeId().getName().getString(), 13) + valueText(*field) + enumChoices(*field) + "\n";
  }
  if (engine) {
    const SoEngineOutputData* outputs = static_cast<SoEngine*>(container)->getOutputData();
    for (int i = 0; outputs && i < outputs->getNumOutputs(); ++i)
      text += "  output " + column(outputs->getOutputName(i).getString(), 14) +
              outputs->getType(i).getName().getString() + "\n";
  }
  // Coin's SoEngine::destroy() evaluates an engine that was never evaluated, and a
  // ClothEngine would then simulate its empty garment (an error message): an engine
  // examined here is kept, one per type, for the program's life.
  engine ? container->unrefNoDelete() : container->unref();
  return text;
}

}  // namespace

std::vector<SoType> typesAddedBy(const std::function<void()>& registerTypes) {
  const std::set<std::string> nodesBefore = namesDerivedFrom(SoNode::getClassTypeId());
  const std::set<std::string> enginesBefore = namesDerivedFrom(SoEngine::getClassTypeId());
  registerTypes();
  std::vector<SoType> added;
  for (SoType base : {SoNode::getClassTypeId(), SoEngine::getClassTypeId()}) {
    const std::set<std::string>& before = base == SoNode::getClassTypeId() ? nodesBefore : enginesBefore;
    for (const std::string& name : namesDerivedFrom(base))
      if (!before.count(name)) added.push_back(SoType::fromName(name.c_str()));
  }
  std::sort(added.begin(), added.end(),
            [](SoType a, SoType b) { return std::string(a.getName().getString()) < b.getName().getString(); });
  return added;
}

std::string describeTypes(const std::vector<SoType>& types) {
  std::string text;
  for (size_t i = 0; i < types.size(); ++i) {
    if (i) text += '\n';  // a blank line between types
    text += describe(types[i]);
  }
  return text;
}

}  // namespace figment::viewer
