// A drape's method as one value: read from the studies' spelling (case free), written
// back, put onto parameters and read off them; a bad text names itself and what is wrong.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/drape/DrapeMethod.h"

using namespace figment;

TEST(DrapeMethod, ReadsTheStudiesSpellingAndPutsItOntoParameters) {
  ClothParameters p;
  DrapeMethod::parse("implicit+penalty:0.02").applyTo(p);
  EXPECT_EQ(p.integrator, Integrator::Implicit);
  EXPECT_EQ(p.implicitSolver.contacts, ContactModel::Penalty);
  EXPECT_DOUBLE_EQ(p.timeStep, 0.02);
  EXPECT_EQ(p.accelerationLimiter, AccelerationLimiter::None);
  EXPECT_DOUBLE_EQ(p.accelerationLimit, ClothParameters{}.accelerationLimit);  // no limit given: kept
  EXPECT_DOUBLE_EQ(p.implicitSolver.maxTimeStep, 0.0);                         // a fixed step
  DrapeMethod::parse("implicit:0.05:0.4").applyTo(p);
  EXPECT_DOUBLE_EQ(p.timeStep, 0.05);
  EXPECT_DOUBLE_EQ(p.implicitSolver.maxTimeStep, 0.4);
  DrapeMethod::parse("HEUN:1.5e-4:Clamp:30").applyTo(p);
  EXPECT_EQ(p.integrator, Integrator::Heun);
  EXPECT_EQ(p.implicitSolver.contacts, ContactModel::Constraints);
  EXPECT_DOUBLE_EQ(p.timeStep, 1.5e-4);
  EXPECT_EQ(p.accelerationLimiter, AccelerationLimiter::Clamp);
  EXPECT_DOUBLE_EQ(p.accelerationLimit, 30.0);
}

TEST(DrapeMethod, WritesTheTextItReadsBack) {
  for (const char* text : {"implicit:0.05", "implicit:0.05:0.4", "implicit+penalty:0.02:0.8", "implicit+penalty:0.05",
                           "heun:0.00015:clamp:30", "euler:0.0001:tanh:12.5", "symplectic:0.0002"}) {
    const DrapeMethod m = DrapeMethod::parse(text);
    EXPECT_EQ(m.text(), text);
    EXPECT_EQ(DrapeMethod::parse(m.text()), m) << text;
  }
  EXPECT_EQ(DrapeMethod::parse("Implicit:5e-2").text(), "implicit:0.05");
}

TEST(DrapeMethod, OfParametersIsWhatTheyDrapeBy) {
  ClothParameters p;
  p.integrator = Integrator::SymplecticEuler;
  p.implicitSolver.contacts = ContactModel::Penalty;
  p.timeStep = 2e-4;
  p.accelerationLimiter = AccelerationLimiter::Tanh;
  p.accelerationLimit = 7.0;
  p.implicitSolver.maxTimeStep = 0.3;
  const DrapeMethod m = DrapeMethod::of(p);
  EXPECT_EQ(m.integrator, Integrator::SymplecticEuler);
  EXPECT_EQ(m.contacts, ContactModel::Penalty);
  EXPECT_DOUBLE_EQ(m.timeStep, 2e-4);
  EXPECT_EQ(m.limiter, AccelerationLimiter::Tanh);
  ASSERT_TRUE(m.limit);
  EXPECT_DOUBLE_EQ(*m.limit, 7.0);
  EXPECT_DOUBLE_EQ(m.maxTimeStep, 0.3);
  ClothParameters back;
  m.applyTo(back);
  EXPECT_EQ(DrapeMethod::of(back), m);
}

TEST(DrapeMethod, ABadTextNamesItselfAndWhatIsWrong) {
  const std::pair<const char*, const char*> cases[] = {{"heun", "wrong number of parts"},
                                                       {"heun:0", "the time step must be > 0"},
                                                       {"heun:x", "\"x\" is not a number"},
                                                       {"implicit+glue:0.05", "no contact model glue"},
                                                       {"heun:1e-4:clamp", "only an implicit step grows"},
                                                       {"implicit:0.05:0.01", "the largest step must not be under"},
                                                       {"implicit:0.05:0.4:1", "no limiter 0.4"},
                                                       {"implicit:0.05:a:b:c", "wrong number of parts"},
                                                       {"heun:1e-4:soft:3", "no limiter soft"},
                                                       {"verlet:0.05", "no integrator verlet"},
                                                       {"heun:1e-4:clamp:many", "\"many\" is not a number"},
                                                       {"heun:-1e-4", "the time step must be > 0"}};
  for (const auto& [text, why] : cases) {
    try {
      DrapeMethod::parse(text);
      ADD_FAILURE() << text << " was read";
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("method \"" + std::string(text) + "\": " + why), std::string::npos) << message;
    }
  }
}

TEST(DrapeMethod, FieldNamesAreTheScenesSpelling) {
  EXPECT_STREQ(fieldName(Integrator::ExplicitEuler), "EULER");
  EXPECT_STREQ(fieldName(Integrator::SymplecticEuler), "SYMPLECTIC");
  EXPECT_STREQ(fieldName(Integrator::Heun), "HEUN");
  EXPECT_STREQ(fieldName(Integrator::Implicit), "IMPLICIT");
  EXPECT_STREQ(fieldName(AccelerationLimiter::None), "NONE");
  EXPECT_STREQ(fieldName(AccelerationLimiter::Clamp), "CLAMP");
  EXPECT_STREQ(fieldName(AccelerationLimiter::Tanh), "TANH");
  EXPECT_STREQ(fieldName(ContactModel::Constraints), "CONSTRAINTS");
  EXPECT_STREQ(fieldName(ContactModel::Penalty), "PENALTY");
}
