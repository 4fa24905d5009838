#pragma once
// HumanBody: MakeHuman's body (CC0, docs/bodies.md) made from macro parameters and typed
// measurements; a MeshFile whose mesh is made instead of read.

#include <Inventor/SbColor.h>
#include <Inventor/fields/SoMFRotation.h>
#include <Inventor/fields/SoMFString.h>
#include <Inventor/fields/SoSFColor.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>

#include <memory>

#include "nodes/body/MeshFile.h"

namespace figment {
struct HumanParameters;
}

/*!
  \class HumanBody nodes/body/HumanBody.h
  \brief MakeHuman's body made to measurements; drawn, and a body wherever a MeshFile is.

  The skin of MakeHuman's hm08 base mesh blended from its macro targets (sim/body/HumanModel.h)
  and, when any measurement field is above 0, made to those measurements
  (sim/body/MeasuredBody.h: each met within 5 mm as figment-measure measures it; the weight is then
  chosen by the solve, and the untyped measurements follow the macro model). Metres, y up, feet
  on the floor, facing +z. Being a MeshFile it draws, offers `point` and `coordIndex`, is a
  ClothEngine's body (its triangles, exactly) and a Mannequin's body; the file fields
  (fileName, metresPerUnit, upAxis, exclude, collisionExclude, crop) are not used and
  fileName must stay "".

  Posed by MakeHuman's own rig and skinning weights (sim/body/RigPose.h, RigSkin.h): `pose`
  picks a preset (sim/body/PosePresets.h), then each bone named in `rotatedJoints` turns by
  its entry of `rotations` (axis and angle, rest frame, about the bone's head, after the
  preset's turn). The joints are placed from the made body's own vertices, so they follow
  its measurements. Drawn and measured posed. As a ClothEngine's body a posed HumanBody
  moves: the garment is put on in the rest pose and the body turns into its pose over the
  first `poseTime` simulated seconds, its triangles rebuilt about every centimetre of
  motion (sim/collision/MovingMeshCollider.h), so a raised arm carries the sleeve up
  instead of passing through it. Only a whole-garment drape moves it (a progressive one is
  refused), and only as the engine's own body (inside a CollisionGroup it stands posed).

  `skinTone` 1 to 10 draws the body in that tone of the Monk Skin Tone scale (Ellis Monk;
  released by Google in 2022, skintone.google, CC BY 4.0): #f6ede4 #f3e7db #f7ead0 #eadaba #d7bd96
  #a07e56 #825c43 #604134 #3a312a #292420; 0 leaves the colour to the scene's Material.

  `baseLayer UNDERWEAR` dresses the body in plain underwear of `baseLayerColor`: briefs, and
  on a women's body (gender below 0.5) a band over the bust, cut from the skin and drawn
  1.5 mm off it (sim/body/BaseLayer.h), inside the cloth's clearance, so garments drape over
  it as over the skin. It is drawn, not a body: the collision surface stays the skin.

  The data is found as io/MakeHumanFiles.h says ($FIGMENT_MAKEHUMAN_DIR, a "makehuman" folder
  on $FIGMENT_MODEL_PATH, the build's data folder); each node reads the targets it blends
  once. A measurement set out of reach, a parameter out of range or missing data is a read
  error naming the node and the measurement (or a posted error when set from code), and the
  node is then empty.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    HumanBody {
        gender 0
        age 0.5
        muscle 0.5
        weight 0.5
        height 0.5
        proportions 0.5
        cupSize 0.5
        stature 0
        bustGirth 0
        underbustGirth 0
        waistGirth 0
        hipGirth 0
        neckGirth 0
        upperArmGirth 0
        thighGirth 0
        pose A_POSE
        rotatedJoints [ ]
        rotations [ ]
        skinning DUAL_QUATERNION
        poseTime 0
        skinTone 0
        baseLayer NONE
        baseLayerColor 0.3 0.3 0.32
    }
  \endcode

  Example (scenes/examples/HumanBody.iv):
  \code
    DEF Body HumanBody { stature 1.68  bustGirth 0.88  waistGirth 0.72  hipGirth 0.96 }
  \endcode
  Posed (scenes/human-posed-arm.iv drapes a T-shirt on such a body):
  \code
    HumanBody { gender 1  pose ARM_RAISED  skinTone 7 }
    HumanBody { rotatedJoints "lowerleg01.L"  rotations 1 0 0 1.047 }   # the left knee bent 60 deg
  \endcode
*/
class HumanBody : public MeshFile {
  typedef MeshFile inherited;
  SO_NODE_HEADER(HumanBody);

 public:
  static void initClass();
  HumanBody();

  // MakeHuman's macro parameters, each in [0, 1] (sim/body/MacroBlend.h). gender: 0 female,
  // 1 male, default 0. age: 0.5 = 25 years, 1 = 90 years. muscle, weight (chosen by the fit
  // when a girth is typed), height (chosen by the fit when stature is typed), proportions
  // (0 uncommon, 1 ideal), cupSize (female only): default 0.5.
  SoSFFloat gender, age, muscle, weight, height, proportions, cupSize;
  // Typed measurements, m (ISO 8559-1, sim/body/BodyMeasurements.h); 0 = not typed. Default 0.
  SoSFFloat stature, bustGirth, underbustGirth, waistGirth, hipGirth, neckGirth, upperArmGirth, thighGirth;

  enum Pose { A_POSE, ARMS_DOWN, ARM_RAISED, WALKING_STEP, SITTING };
  enum Skinning { LINEAR_BLEND, DUAL_QUATERNION };
  // The preset (sim/body/PosePresets.h). Default A_POSE (MakeHuman's rest pose).
  SoSFEnum pose;
  // Bones to turn, by the rig's names (e.g. "upperarm01.L", "lowerleg01.R"; .L is the
  // body's left, +x), and their rotations, one each (rest frame, about the bone's head),
  // after the preset's. Default [ ] and [ ].
  SoMFString rotatedJoints;
  SoMFRotation rotations;
  // How the skin follows the bones (sim/body/RigSkin.h). Default DUAL_QUATERNION.
  SoSFEnum skinning;
  // Simulated seconds a drape takes to turn the body from rest into its pose; 0: as long
  // as its farthest-moving point needs at 0.25 m/s. Default 0. Must be >= 0.
  SoSFFloat poseTime;
  // The Monk Skin Tone scale's tone, 1 (lightest) to 10 (deepest), as the body's diffuse
  // colour; 0: the scene's Material. Default 0.
  SoSFInt32 skinTone;
  // The scale's ten colours (sRGB, 0..1), tone 1 first.
  static SbColor monkSkinTone(int tone);
  // Plain underwear drawn on the skin (the class comment), or none. Default NONE. Changing
  // either field redraws the layer without making the body again.
  enum BaseLayer { NONE, UNDERWEAR };
  SoSFEnum baseLayer;
  SoSFColor baseLayerColor;  // default a dark neutral grey, 0.3 0.3 0.32

  // The base layer's surface as drawn (empty with baseLayer NONE or no body).
  figment::TriangleMesh baseLayerSurface() const;

  // As a ClothEngine's body: the rest body moving into its pose (posed), else the
  // MeshFile's collider. Throws as MeshFile's.
  std::shared_ptr<const figment::Collider> bodyCollider() const override;
  // The made body in its rest pose (A_POSE), its vertices numbered as the posed
  // collisionSurface()'s: what a posed body's fit is measured on (sim/fit/PosedSkin.h).
  // The collisionSurface() itself when not posed; empty when not made.
  figment::TriangleMesh restSurface() const;

 protected:
  ~HumanBody() override;
  bool load(SoInput* in) override;
  bool isLoadOption(const SoField* field) const override;
  void notify(SoNotList* list) override;
  void copyContents(const SoFieldContainer* from, SbBool copyConnections) override;

 private:
  struct Data;
  std::unique_ptr<Data> data_;  // MakeHuman's targets, read on first use
  figment::TriangleMesh posed(const figment::HumanParameters& parameters, figment::TriangleMesh rest);
  void colourSkin();
  void dressBaseLayer();
};
