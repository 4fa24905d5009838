#pragma once
// A symmetric matrix's eigenvalues, compiled once for the tests that check a stiffness is
// positive semi-definite: Eigen's SelfAdjointEigenSolver, instantiated in a test's own file,
// took 15 to 19 of its 20 to 23 s to compile (test_MembraneElement, test_ClothModel).

#include <Eigen/Core>

namespace figment::test {

// Ascending. `symmetric` must be square and symmetric (its lower triangle is read).
Eigen::VectorXd symmetricEigenvalues(const Eigen::MatrixXd& symmetric);

}  // namespace figment::test
