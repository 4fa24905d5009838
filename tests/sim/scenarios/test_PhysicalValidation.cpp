// The cloth model against closed-form elasticity at static equilibrium:
//  - a long strip hanging under its own weight stretches as Hooke's law says (sigma = E eps
//    with the weight below each cross-section) and narrows by Poisson's ratio;
//  - a cantilevered strip droops as the small-deflection beam formula delta = q L^4 / 8D
//    says, on right-triangle and equilateral meshes, for several thicknesses.
// Both run with symplectic Euler: the equilibrium does not depend on the integrator, and it
// stays stable for the undamped high modes at the step sizes used here with one force
// evaluation per step. Air resistance (mass-proportional damping) settles every mode and
// vanishes at rest. Both run again with the implicit integrator at dt = 1/100 s, far
// beyond the explicit limit, to the same tolerances.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/cloth/ClothSolver.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
constexpr double kG = 9.81;             // m/s^2, |gravity| in ClothParameters
constexpr double kImplicitStep = 0.01;  // s

// `explicitStep`: symplectic Euler's stable step; with Integrator::Implicit the step is
// kImplicitStep instead.
ClothParameters settling(const Material& material, double lowestFrequency, double explicitStep, double restSpeed,
                         Integrator integrator) {
  ClothParameters p;
  p.material = material;
  p.integrator = integrator;
  p.strainRateDamping = 0.0;
  // Critical damping of the slowest mode: a = -(k / rho h) v with k / rho h = 2 omega_1.
  p.airResistance = 2.0 * lowestFrequency * p.material.arealDensity();
  p.timeStep = integrator == Integrator::Implicit ? kImplicitStep : explicitStep;
  p.maxTime = std::max(40.0 / lowestFrequency, 500 * p.timeStep);  // implicit: 500 steps at most
  p.rest.speedThreshold = restSpeed;
  p.rest.window = 2.0 / lowestFrequency;
  return p;
}
}  // namespace

namespace {
void expectHookesHangingStrip(Integrator integrator) {
  // 1 m x 5 cm, 4 x 80 sections of 1.25 cm, pinned along its top edge (y = 0). At depth s
  // the section carries the weight below it: sigma(s) = rho g (L - s), eps = sigma / E, so
  //   elongation  dL = rho g L^2 / (2 E)  and relative narrowing  nu eps(s).
  // With the default cloth (E = 1 MPa, rho = 300 kg/m^3) eps <= 2.9e-3: the Green strain's
  // eps^2 / 2 changes both by <= 0.3 %, well inside the tolerances. The pinned top row
  // cannot narrow (Saint-Venant, within about a width of the top): the narrowing is read in
  // the middle third only; its effect on dL is ~ nu^2 w / L ~ 0.5 %.
  const int across = 4, along = 80;
  const double width = 0.05, length = 1.0;
  const Material m;                                                 // the default cloth
  const double waveSpeed = std::sqrt(m.youngsModulus / m.density);  // 58 m/s
  const double omega1 = M_PI * waveSpeed / (2.0 * length);          // fixed-free bar
  const double expectedElongation = m.density * kG * length * length / (2.0 * m.youngsModulus);
  const ClothParameters p = settling(m, omega1, 5e-5, 1e-3 * expectedElongation * omega1, integrator);
  const TriangleMesh strip = meshes::grid(across, along, width, length);
  ClothSolver solver(strip, p, nullptr);
  for (int i = 0; i <= across; ++i) solver.pin(i);
  const DrapeResult result = solver.run();
  ASSERT_TRUE(result.atRest) << "t = " << result.simulatedTime;
  const auto& x = solver.positions();
  auto node = [&](int i, int j) { return i + j * (across + 1); };

  double elongation = 0.0;
  for (int i = 0; i <= across; ++i) elongation += strip.vertices[node(i, along)].y() - x[node(i, along)].y();
  elongation /= across + 1;
  EXPECT_NEAR(elongation, expectedElongation, 0.02 * expectedElongation);  // 1.47 mm

  for (int j = along / 3; j <= 2 * along / 3; j += 5) {
    const double s = length * j / along;
    const double strain = m.density * kG * (length - s) / m.youngsModulus;
    const double narrowing = 1.0 - (x[node(across, j)].x() - x[node(0, j)].x()) / width;
    EXPECT_NEAR(narrowing, m.poissonRatio * strain, 0.05 * m.poissonRatio * strain) << "s = " << s << " m";
  }
}
}  // namespace

TEST(PhysicalValidation, HangingStripStretchesAndNarrowsAsHookeSays) {
  expectHookesHangingStrip(Integrator::SymplecticEuler);
}

TEST(PhysicalValidation, ImplicitHangingStripStretchesAndNarrowsAsHookeSays) {
  expectHookesHangingStrip(Integrator::Implicit);
}

namespace {
// Tip droop (m) of a strip L x b lying in the x-z plane, clamped along its short edge at
// x = 0 by pinning the nodes at x = -L/n and x = 0 (so the edge cannot rotate), sagging
// under its own weight along -y. `mesh` builds n sections along x and 4 across.
double cantileverDroop(const TriangleMesh& mesh, const std::vector<int>& clamped, const std::vector<int>& tip,
                       double youngsModulus, double thickness, double length, double spacing, Integrator integrator) {
  Material m;
  m.youngsModulus = youngsModulus;
  m.thickness = thickness;
  m.poissonRatio = 0.0;
  const double D = m.bendingStiffness();
  const double stiffnessPerMass = D / m.arealDensity();
  // Stable steps: membrane waves (speed c, ~3 c / spacing) and the stiffest hinge mode
  // (~sqrt(500 D / rho h) / spacing^2, the discrete-shell hinges of a few sections).
  const double waveSpeed = std::sqrt(youngsModulus / m.density);
  const double fastest = std::max(3.0 * waveSpeed / spacing, std::sqrt(500.0 * stiffnessPerMass) / (spacing * spacing));
  const double omega1 = 3.516 * std::sqrt(stiffnessPerMass) / (length * length);  // first cantilever mode
  const double beamDroop = m.arealDensity() * kG * std::pow(length, 4) / (8.0 * D);
  const ClothParameters p = settling(m, omega1, 1.0 / fastest, 1e-4 * beamDroop * omega1, integrator);
  ClothSolver solver(mesh, p, nullptr);
  for (int i : clamped) solver.pin(i);
  const DrapeResult result = solver.run();
  EXPECT_TRUE(result.atRest) << "h = " << thickness << " m, t = " << result.simulatedTime;
  double droop = 0.0;
  for (int i : tip) droop -= solver.positions()[i].y() - mesh.vertices[i].y();
  return droop / tip.size();
}
}  // namespace

namespace {
void expectBeamFormulaDroop(Integrator integrator) {
  // q = rho g h per area, D = E h^3 / 12 (nu = 0: a strip is free to curve across, so the
  // plate's 1 - nu^2 would not apply); delta = q L^4 / 8D. E = 4 MPa, L = 10 cm, b = 2 cm;
  // h = 4, 6, 8 mm keep delta / L at 0.069, 0.031, 0.017 (small deflection). The clamp
  // pins two columns of nodes, so the edge cannot rotate. Tolerances, from the case: no
  // strip droops more than 1 % under the formula (which, for small deflection, is an
  // upper bound: at delta / L = 0.069 the shortening costs (delta / L)^2 < 0.5 %); right
  // triangles bend about hinges across the strip and come within 1 % above it (measured
  // 0.03-0.7 %); the equilateral strip's hinges zig-zag at 30 degrees to its axis, which
  // leaves it a little softer: within 5 % (measured 3.8-4.4 %).
  const double E = 4e6, L = 0.1, b = 0.02;
  const int n = 12, across = 4;
  const double dx = L / n;
  // Right triangles: nodes (i, j) = i + j (n + 2), i along x from -dx, j across.
  const TriangleMesh grid = meshes::grid(n + 1, across, L + dx, b, Vec3(-dx, 0, 0), Vec3::UnitX(), Vec3::UnitZ());
  std::vector<int> gridClamp, gridTip;
  for (int j = 0; j <= across; ++j) {
    gridClamp.insert(gridClamp.end(), {j * (n + 2), 1 + j * (n + 2)});
    gridTip.push_back(n + 1 + j * (n + 2));
  }
  // Equilateral triangles in rows across the strip, dx apart along x from -dx.
  const TriangleMesh equilateral =
      meshes::equilateralStrip(across, n + 1, dx * 2.0 / std::sqrt(3.0), Vec3(-dx, 0, 0), Vec3::UnitZ(), Vec3::UnitX());
  std::vector<int> equilateralClamp, equilateralTip;
  for (int i = 0; i <= across; ++i) {
    equilateralClamp.insert(equilateralClamp.end(), {i, i + across + 1});
    equilateralTip.push_back(i + (n + 1) * (across + 1));
  }
  struct Strip {
    const char* name;
    const TriangleMesh& mesh;
    const std::vector<int>&clamp, &tip;
    double softerBy;  // the most it may droop beyond the formula, a share of it
  };
  const Material cloth;
  for (const Strip& strip : {Strip{"right triangles", grid, gridClamp, gridTip, 0.01},
                             Strip{"equilateral", equilateral, equilateralClamp, equilateralTip, 0.05}})
    for (double h : {0.004, 0.006, 0.008}) {
      const double q = cloth.density * kG * h, D = E * h * h * h / 12.0;
      const double expected = q * std::pow(L, 4) / (8.0 * D);
      const double droop = cantileverDroop(strip.mesh, strip.clamp, strip.tip, E, h, L, dx, integrator);
      EXPECT_GT(droop, expected * 0.99) << strip.name << ", h = " << h << " m";
      EXPECT_LT(droop, expected * (1.0 + strip.softerBy)) << strip.name << ", h = " << h << " m";
    }
}
}  // namespace

TEST(PhysicalValidation, CantileverDroopsAsTheBeamFormulaSays) {
  expectBeamFormulaDroop(Integrator::SymplecticEuler);
}

TEST(PhysicalValidation, ImplicitCantileverDroopsAsTheBeamFormulaSays) {
  expectBeamFormulaDroop(Integrator::Implicit);
}
