#include "guard/FieldDeclarations.h"

#include <Inventor/SbName.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/fields/SoFieldContainer.h>
#include <Inventor/lists/SoFieldList.h>

namespace figment::guard {

namespace {

// VRML97's kinds of field, which PROTO interfaces and scripts give before a field's type.
bool isKindOfField(const std::string& word) {
  return word == "field" || word == "exposedField" || word == "eventIn" || word == "eventOut";
}

std::string article(const std::string& word) {
  return std::string("AEFHILMNORSX").find(word.front()) == std::string::npos ? "a " + word : "an " + word;
}

}  // namespace

const FieldDeclarations::ClassFields& FieldDeclarations::classFields(SoType type) {
  const std::string name = type.getName().getString();
  const auto known = classes_.find(name);
  if (known != classes_.end()) return known->second;
  ClassFields& out = classes_[name];
  if (!type.isDerivedFrom(SoFieldContainer::getClassTypeId()) || !type.canCreateInstance()) return out;
  // Two nodes of the class tell whether its nodes share one field list; one lists the fields.
  auto* first = static_cast<SoFieldContainer*>(type.createInstance());
  auto* second = static_cast<SoFieldContainer*>(type.createInstance());
  if (!first || !second) return out;
  first->ref();
  second->ref();
  out.shared = first->getFieldData() == second->getFieldData();
  SoFieldList fields;
  first->getFields(fields);
  for (int i = 0; i < fields.getLength(); ++i) {
    SbName fieldName;
    first->getFieldName(fields[i], fieldName);
    out.fields.push_back({fieldName.getString(), fields[i]->getTypeId()});
  }
  second->unref();
  first->unref();
  return out;
}

// Whether `word`, read as the first name in a node's body, starts a declaration Coin would add
// to the class's shared field list: "fields", where the class has no field of that name.
bool FieldDeclarations::startsDeclaration(const std::string& word) {
  if (word != "fields" || !bodyOpened_ || names_.empty()) return false;
  const SoType type = SoType::fromName(names_.back().c_str());
  if (type.isBad()) return false;  // an unknown node: its own fields
  const ClassFields& fields = classFields(type);
  if (!fields.shared) return false;
  for (const Field& field : fields.fields)
    if (field.name == word) return false;
  fields_ = &fields;
  className_ = node_ = names_.back();
  if (names_.size() == 3 && names_[0] == "DEF") node_ += " '" + names_[1] + "'";
  return true;
}

std::string FieldDeclarations::check(const std::string& field) const {
  const std::string declared = node_ + ": fields [ " + declaredType_ + " " + field + " ] declares ";
  const SoType type = SoType::fromName(declaredType_.c_str());
  for (const Field& known : fields_->fields) {
    if (known.name != field) continue;
    if (known.type == type) return "";
    const std::string is = known.type.getName().getString();
    return declared + field + " " + article(declaredType_) + ", but it is " + article(is);
  }
  return declared + "a field " + className_ + " does not have";
}

std::string FieldDeclarations::seeName(const SbName& name) {
  const std::string word = name.getString();
  switch (stage_) {
    case Stage::kType:
      if (isKindOfField(word)) {
        stage_ = Stage::kOutside;
        return node_ + ": fields [ " + word +
               " ... ] gives a kind of field, which only PROTO interfaces and "
               "scripts declare";
      }
      declaredType_ = word;
      stage_ = Stage::kName;
      return "";
    case Stage::kName: {
      std::string problem = check(word);
      stage_ = problem.empty() ? Stage::kType : Stage::kOutside;  // Coin stops reading there
      return problem;
    }
    case Stage::kOutside:
      break;
  }
  if (startsDeclaration(word)) stage_ = Stage::kType;
  names_.push_back(word);
  if (names_.size() > 3) names_.erase(names_.begin());
  charsSinceName_ = 0;
  bodyOpened_ = false;
  return "";
}

void FieldDeclarations::seeChar(char c) {
  if (stage_ != Stage::kOutside) {
    if (c == ']') stage_ = Stage::kOutside;  // Coin's end of the declaration
    return;
  }
  bodyOpened_ = ++charsSinceName_ == 1 && c == '{';
}

}  // namespace figment::guard
