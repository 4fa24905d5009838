#include "support/Eigenvalues.h"

#include <Eigen/Eigenvalues>

namespace figment::test {

Eigen::VectorXd symmetricEigenvalues(const Eigen::MatrixXd& symmetric) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(symmetric, Eigen::EigenvaluesOnly).eigenvalues();
}

}  // namespace figment::test
