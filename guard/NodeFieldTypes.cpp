#include "guard/NodeFieldTypes.h"

#include <Inventor/VRMLnodes/SoVRMLAppearance.h>
#include <Inventor/VRMLnodes/SoVRMLAudioClip.h>
#include <Inventor/VRMLnodes/SoVRMLColor.h>
#include <Inventor/VRMLnodes/SoVRMLCoordinate.h>
#include <Inventor/VRMLnodes/SoVRMLFontStyle.h>
#include <Inventor/VRMLnodes/SoVRMLGeometry.h>
#include <Inventor/VRMLnodes/SoVRMLMaterial.h>
#include <Inventor/VRMLnodes/SoVRMLMovieTexture.h>
#include <Inventor/VRMLnodes/SoVRMLNormal.h>
#include <Inventor/VRMLnodes/SoVRMLShape.h>
#include <Inventor/VRMLnodes/SoVRMLSound.h>
#include <Inventor/VRMLnodes/SoVRMLText.h>
#include <Inventor/VRMLnodes/SoVRMLTexture.h>
#include <Inventor/VRMLnodes/SoVRMLTextureCoordinate.h>
#include <Inventor/VRMLnodes/SoVRMLTextureTransform.h>
#include <Inventor/fields/SoMFNode.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/nodes/SoSceneTexture2.h>
#include <Inventor/nodes/SoShaderObject.h>
#include <Inventor/nodes/SoShaderParameter.h>
#include <Inventor/nodes/SoShaderProgram.h>
#include <Inventor/nodes/SoShape.h>
#include <Inventor/nodes/SoTransparencyType.h>
#include <Inventor/nodes/SoVertexProperty.h>
#include <Inventor/nodes/SoVertexShape.h>

#include <vector>

#include "guard/NodeLinks.h"

namespace figment::guard {

namespace {

// A field of `owner` (and of the types derived from it) named `field` takes a node of one of
// the types `takes`. The VRML97 fields are typed by the specification (ISO/IEC 14772-1, 6.x).
struct FieldRule {
  SoType owner;
  const char* field;
  std::vector<SoType> takes;
};

const std::vector<FieldRule>& fieldRules() {
  static const std::vector<FieldRule> rules{
      {SoVertexShape::getClassTypeId(), "vertexProperty", {SoVertexProperty::getClassTypeId()}},
      {SoVRMLShape::getClassTypeId(), "appearance", {SoVRMLAppearance::getClassTypeId()}},
      {SoVRMLShape::getClassTypeId(), "geometry", {SoShape::getClassTypeId()}},
      {SoVRMLAppearance::getClassTypeId(), "material", {SoVRMLMaterial::getClassTypeId()}},
      {SoVRMLAppearance::getClassTypeId(), "texture", {SoVRMLTexture::getClassTypeId()}},
      {SoVRMLAppearance::getClassTypeId(), "textureTransform", {SoVRMLTextureTransform::getClassTypeId()}},
      // VRMLIndexedFaceSet, VRMLIndexedLineSet, VRMLPointSet, VRMLElevationGrid.
      {SoVRMLGeometry::getClassTypeId(), "coord", {SoVRMLCoordinate::getClassTypeId()}},
      {SoVRMLGeometry::getClassTypeId(), "normal", {SoVRMLNormal::getClassTypeId()}},
      {SoVRMLGeometry::getClassTypeId(), "color", {SoVRMLColor::getClassTypeId()}},
      {SoVRMLGeometry::getClassTypeId(), "texCoord", {SoVRMLTextureCoordinate::getClassTypeId()}},
      {SoVRMLText::getClassTypeId(), "fontStyle", {SoVRMLFontStyle::getClassTypeId()}},
      {SoVRMLSound::getClassTypeId(),
       "source",
       {SoVRMLAudioClip::getClassTypeId(), SoVRMLMovieTexture::getClassTypeId()}},
      {SoShaderProgram::getClassTypeId(), "shaderObject", {SoShaderObject::getClassTypeId()}},
      {SoShaderObject::getClassTypeId(), "parameter", {SoShaderParameter::getClassTypeId()}},
      {SoSceneTexture2::getClassTypeId(), "sceneTransparencyType", {SoTransparencyType::getClassTypeId()}},
  };
  return rules;
}

std::string typeName(SoType type) {
  return type.getName().getString();
}

std::string article(const std::string& word) {
  return std::string("AEIOU").find(word.front()) == std::string::npos ? "a " + word : "an " + word;
}

std::string belongs(const std::vector<SoType>& takes) {
  std::string text;
  for (std::size_t i = 0; i < takes.size(); ++i) text += (i == 0 ? "" : " or ") + article(typeName(takes[i]));
  return text;
}

bool takes(const std::vector<SoType>& types, const SoNode* held) {
  for (const SoType type : types)
    if (held->isOfType(type)) return true;
  return false;
}

// "" when every node `field` holds is of a type in `rule`, else the line naming the first.
std::string mistyped(const SoNode& owner, const FieldRule& rule, const SoField& field) {
  const auto line = [&](const std::string& where, const SoNode& held) {
    return describeNode(owner) + ": " + where + " holds " + article(describeNode(held)) + ", where " +
           belongs(rule.takes) + " belongs";
  };
  if (field.isOfType(SoSFNode::getClassTypeId())) {
    const SoNode* held = static_cast<const SoSFNode&>(field).getValue();
    return held && !takes(rule.takes, held) ? line(rule.field, *held) : "";
  }
  const auto& many = static_cast<const SoMFNode&>(field);
  for (int i = 0; i < many.getNum(); ++i)
    if (many[i] && !takes(rule.takes, many[i]))
      return line(std::string(rule.field) + "[" + std::to_string(i) + "]", *many[i]);
  return "";
}

std::string firstMistypedField(const SoNode& node) {
  for (const FieldRule& rule : fieldRules()) {
    if (!node.isOfType(rule.owner)) continue;
    const SoField* field = node.getField(rule.field);
    if (!field) continue;
    if (std::string problem = mistyped(node, rule, *field); !problem.empty()) return problem;
  }
  return "";
}

}  // namespace

std::string firstMistypedNodeField(const SoNode* root) {
  return firstProblemAmongLinkedNodes(root, firstMistypedField);
}

}  // namespace figment::guard
