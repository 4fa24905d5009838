// Fitting a body to measurements. Based on Gauss-Newton with bounds by projection (Nocedal &
// Wright, Numerical Optimization, §10.3 and §16.7): x <- clamp(x - J^+ r), J by forward
// differences; a goal whose parameter sits at a bound with the residual pushing beyond it
// cannot be met, and its measurement there is the nearest reachable value.

#include "sim/body/BodyFit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace figment {

namespace {

constexpr double kDifferenceStep = 0.04;  // parameter units: a step of ~1 cm in a girth

struct Unknown {
  std::string key;        // measurement
  std::string parameter;  // "height" (macro) or a measure target key
  double low, high;
};

double get(const HumanParameters& p, const Unknown& u) {
  if (u.parameter == "height") return p.macro.height;
  const auto it = p.measures.find(u.parameter);
  return it == p.measures.end() ? 0.0 : it->second;
}

void set(HumanParameters& p, const Unknown& u, double value) {
  value = std::clamp(value, u.low, u.high);
  if (u.parameter == "height")
    p.macro.height = value;
  else
    p.measures[u.parameter] = value;
}

std::vector<Unknown> unknownsFor(const std::vector<MeasurementGoal>& goals) {
  std::vector<Unknown> unknowns;
  std::set<std::string> seen;
  for (const MeasurementGoal& goal : goals) {
    if (!seen.insert(goal.key).second) throw std::invalid_argument(goal.key + " is given twice");
    if (!(goal.value > 0)) throw std::invalid_argument(goal.key + " = " + std::to_string(goal.value) + " m is not > 0");
    const auto& keys = fittedKeys();
    const auto it = std::find_if(keys.begin(), keys.end(), [&](const auto& k) { return k.first == goal.key; });
    if (it == keys.end()) throw std::invalid_argument("no measurement '" + goal.key + "' to fit");
    const bool macro = it->second == "height";
    unknowns.push_back({goal.key, it->second, macro ? 0.0 : -1.0, 1.0});
  }
  return unknowns;
}

struct Evaluation {
  TriangleMesh body;
  BodyMeasurements measured;
  Eigen::VectorXd residual;  // m, measured - goal
};

Evaluation evaluate(const HumanModel& model, const HumanParameters& p, const std::vector<MeasurementGoal>& goals) {
  Evaluation e;
  e.body = model.make(p);
  e.measured = measureBody(e.body);
  e.residual.resize(Eigen::Index(goals.size()));
  for (size_t i = 0; i < goals.size(); ++i)
    e.residual[Eigen::Index(i)] = e.measured.byName(goals[i].key) - goals[i].value;
  return e;
}

Eigen::MatrixXd jacobian(const HumanModel& model, const HumanParameters& p, const std::vector<Unknown>& unknowns,
                         const std::vector<MeasurementGoal>& goals, const Eigen::VectorXd& residual) {
  const Eigen::Index n = Eigen::Index(unknowns.size());
  Eigen::MatrixXd J(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Unknown& u = unknowns[size_t(j)];
    const double x = get(p, u);
    const double step = x + kDifferenceStep <= u.high ? kDifferenceStep : -kDifferenceStep;  // stay in range
    HumanParameters moved = p;
    set(moved, u, x + step);
    J.col(j) = (evaluate(model, moved, goals).residual - residual) / step;
  }
  return J;
}

// The macro weight at which the typed girths' errors sum to zero (the measure targets then
// shape what the weight does not: a body of 104 cm waist is a heavier body, not an average one
// with its waist pushed out). Bisection: the girths grow with the weight.
double naturalWeight(const HumanModel& model, HumanParameters p, const std::vector<MeasurementGoal>& goals) {
  std::vector<MeasurementGoal> girths;
  for (const MeasurementGoal& goal : goals)
    if (goal.key.ends_with("_girth")) girths.push_back(goal);
  if (girths.empty()) return p.macro.weight;
  double low = 0, high = 1;
  for (int i = 0; i < 7; ++i) {
    p.macro.weight = 0.5 * (low + high);
    (evaluate(model, p, girths).residual.sum() > 0 ? high : low) = p.macro.weight;
  }
  return 0.5 * (low + high);
}

// Moves `p` along `delta` (clamped to the parameters' ranges), halving the step until the
// residual shrinks (a landmark moving to another level makes the measurements only piecewise
// smooth); false when no step of at least 1/16 does.
bool stepAlong(const HumanModel& model, const std::vector<Unknown>& unknowns, const std::vector<MeasurementGoal>& goals,
               const Eigen::VectorXd& delta, HumanParameters& p, Evaluation& e) {
  for (double fraction = 1; fraction >= 1.0 / 16; fraction *= 0.5) {
    HumanParameters next = p;
    for (size_t j = 0; j < unknowns.size(); ++j)
      set(next, unknowns[j], get(next, unknowns[j]) + fraction * delta[Eigen::Index(j)]);
    Evaluation moved = evaluate(model, next, goals);
    if (moved.residual.norm() < e.residual.norm()) {
      p = next;
      e = std::move(moved);
      return true;
    }
  }
  return false;
}

[[noreturn]] void refuse(const std::vector<MeasurementGoal>& goals, const Evaluation& e) {
  Eigen::Index worst = 0;
  e.residual.cwiseAbs().maxCoeff(&worst);
  const MeasurementGoal& goal = goals[size_t(worst)];
  char line[200];
  std::snprintf(line, sizeof line, "%s %.3f m is out of reach with the other measurements: the nearest is %.3f m",
                goal.key.c_str(), goal.value, goal.value + e.residual[worst]);
  throw UnreachableMeasurement(line);
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& fittedKeys() {
  static const std::vector<std::pair<std::string, std::string>> keys = {{"stature", "height"},
                                                                        {"bust_girth", "bust"},
                                                                        {"underbust_girth", "underbust"},
                                                                        {"waist_girth", "waist"},
                                                                        {"hip_girth", "hips"},
                                                                        {"neck_girth", "neck"},
                                                                        {"shoulder_width", "shoulder"},
                                                                        {"upper_arm_girth", "upperarm"},
                                                                        {"thigh_girth", "thigh"},
                                                                        {"inside_leg", "upperleg_height"},
                                                                        {"arm_length", "lowerarm_length"}};
  return keys;
}

BodyFitResult fitBody(const HumanModel& model, const HumanParameters& start, const std::vector<MeasurementGoal>& goals,
                      const BodyFitOptions& options) {
  const std::vector<Unknown> unknowns = unknownsFor(goals);
  BodyFitResult result;
  result.parameters = start;
  result.parameters.macro.weight = naturalWeight(model, start, goals);
  Evaluation e = evaluate(model, result.parameters, goals);
  // aim well inside the tolerance: the measurement's own steps (1 mm levels) stay below it
  const double aim = 0.25 * options.tolerance;
  const auto worst = [](const Evaluation& at) { return at.residual.size() ? at.residual.cwiseAbs().maxCoeff() : 0.0; };
  for (; result.iterations < options.maxIterations && worst(e) > aim; ++result.iterations) {
    const Eigen::MatrixXd J = jacobian(model, result.parameters, unknowns, goals, e.residual);
    const Eigen::VectorXd delta = J.colPivHouseholderQr().solve(-e.residual);
    if (!stepAlong(model, unknowns, goals, delta, result.parameters, e)) break;  // as near as it gets
  }
  if (worst(e) > options.tolerance) refuse(goals, e);
  result.body = std::move(e.body);
  result.achieved = e.measured;
  return result;
}

}  // namespace figment
