#pragma once
// HumanBody: MakeHuman's body (CC0, docs/bodies.md) made from macro parameters and typed
// measurements; a MeshFile whose mesh is made instead of read.

#include <Inventor/fields/SoSFFloat.h>

#include <memory>

#include "nodes/body/MeshFile.h"

/*!
  \class HumanBody nodes/body/HumanBody.h
  \brief MakeHuman's body made to measurements; drawn, and a body wherever a MeshFile is.

  The skin of MakeHuman's hm08 base mesh blended from its macro targets (sim/body/HumanModel.h)
  and, when any measurement field is above 0, fitted to those measurements
  (sim/body/BodyFit.h: each met within 5 mm as figment-measure measures it; the weight is then
  chosen by the fit, and the untyped measurements follow the macro model). Metres, y up, feet
  on the floor, facing +z. Being a MeshFile it draws, offers `point` and `coordIndex`, is a
  ClothEngine's body (its triangles, exactly) and a Mannequin's body; the file fields
  (fileName, metresPerUnit, upAxis, exclude, collisionExclude, crop) are not used and
  fileName must stay "".

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
    }
  \endcode

  Example (scenes/examples/HumanBody.iv):
  \code
    DEF Body HumanBody { stature 1.68  bustGirth 0.88  waistGirth 0.72  hipGirth 0.96 }
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

 protected:
  ~HumanBody() override;
  bool load(SoInput* in) override;
  bool isLoadOption(const SoField* field) const override;

 private:
  struct Data;
  std::unique_ptr<Data> data_;  // MakeHuman's targets, read on first use
};
