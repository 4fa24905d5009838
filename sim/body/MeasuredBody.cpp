// Fitting a body to measurements. Based on Gauss-Newton with bounds by projection (Nocedal &
// Wright, Numerical Optimization, §10.3 and §16.7): x <- clamp(x - J^-1 r), J by forward
// differences once and then by Broyden's rank-one updates (ibid. §11.1: each step's change in
// the residuals corrects J along the step, so a step costs one body, not one per unknown); a
// goal whose parameter sits at a bound with the residual pushing beyond it cannot be met,
// and its measurement there is the nearest reachable value. The body's mass first, along a
// path through MakeHuman's weight and muscle, by the Illinois variant of regula falsi
// (Dowell & Jarratt 1971): the girths grow with it, and their errors' sum changes sign once.

#include "sim/body/MeasuredBody.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace figment {

namespace {

constexpr double kDifferenceStep = 0.04;  // parameter units: a step of ~1 cm in a girth
constexpr double kMassLow = -1, kMassHigh = 2;

// How a goal's parameter goes on past its measure target's end (x beyond +-1, up to +-2): the
// female bust by the cup size (to 0 below, to 1 above), the waist by the stomach's belly target
// above, the hips by the buttocks' volume target either way (issue 43: a DOB 54 bust, the
// men's bellies, a straight women's figure whose hips are no fuller than her bust).
enum class Extension { None, CupSize, Stomach, Buttocks };

// One goal's parameter: the macro height, or a measure target, continued past its ends by its
// extensions.
struct Unknown {
  std::string key;        // measurement
  std::string parameter;  // "height" (macro) or a measure target key
  double low, high;
  Extension below = Extension::None, above = Extension::None;
};

Unknown unknownFor(const std::string& key, const std::string& parameter, const HumanParameters& start) {
  Unknown u{key, parameter, parameter == "height" ? 0.0 : -1.0, 1.0};
  const bool female = start.macro.gender < 1.0;
  if (parameter == "bust" && female && start.macro.cupSize > 0.0) u.below = Extension::CupSize;
  if (parameter == "bust" && female && start.macro.cupSize < 1.0) u.above = Extension::CupSize;
  if (parameter == "waist") u.above = Extension::Stomach;
  if (parameter == "hips") u.below = u.above = Extension::Buttocks;
  if (u.below != Extension::None) u.low = -2.0;
  if (u.above != Extension::None) u.high = 2.0;
  return u;
}

std::vector<Unknown> unknownsFor(const std::vector<MeasurementGoal>& goals, const HumanParameters& start) {
  std::vector<Unknown> unknowns;
  std::set<std::string> seen;
  for (const MeasurementGoal& goal : goals) {
    if (!seen.insert(goal.key).second) throw std::invalid_argument(goal.key + " is given twice");
    if (!(goal.value > 0)) throw std::invalid_argument(goal.key + " = " + std::to_string(goal.value) + " m is not > 0");
    const auto& keys = measurableKeys();
    const auto it = std::find_if(keys.begin(), keys.end(), [&](const auto& k) { return k.first == goal.key; });
    if (it == keys.end()) throw std::invalid_argument("no measurement '" + goal.key + "' to fit");
    unknowns.push_back(unknownFor(goal.key, it->second, start));
  }
  return unknowns;
}

// Sets `p`'s extension `e` `amount` (0 to 1) past its target's end, `sign` the side (+1 above).
void extend(HumanParameters& p, const HumanParameters& start, Extension e, double amount, double sign) {
  switch (e) {
    case Extension::CupSize:
      p.macro.cupSize =
          sign > 0 ? start.macro.cupSize + amount * (1 - start.macro.cupSize) : start.macro.cupSize * (1 - amount);
      break;
    case Extension::Stomach:
      p.measures["stomach"] = sign * amount;
      break;
    case Extension::Buttocks:
      p.measures["buttocks"] = sign * amount;
      break;
    case Extension::None:
      break;
  }
}

Eigen::VectorXd startingPoint(const HumanParameters& start, const std::vector<Unknown>& unknowns) {
  Eigen::VectorXd x(Eigen::Index(unknowns.size()));
  for (size_t j = 0; j < unknowns.size(); ++j) {
    const Unknown& u = unknowns[j];
    const auto it = start.measures.find(u.parameter);
    x[Eigen::Index(j)] = u.parameter == "height" ? start.macro.height : it == start.measures.end() ? 0.0 : it->second;
  }
  return x;
}

// `start` with the mass `s` and the unknowns `x` (each clamped to its range) applied. The
// mass path: weight s with the muscle as started for s in [0, 1]; beyond, the weight stays
// at its end and the muscle falls linearly to 0 at s = -1 and s = 2 (MakeHuman's thinnest
// body is its least weight and muscle, its heaviest its most weight and least muscle).
HumanParameters applied(const HumanParameters& start, double s, const std::vector<Unknown>& unknowns,
                        const Eigen::VectorXd& x) {
  HumanParameters p = start;
  s = std::clamp(s, kMassLow, kMassHigh);
  p.macro.weight = std::clamp(s, 0.0, 1.0);
  if (s < 0) p.macro.muscle = start.macro.muscle * (1 + s);
  if (s > 1) p.macro.muscle = start.macro.muscle * (2 - s);
  for (size_t j = 0; j < unknowns.size(); ++j) {
    const Unknown& u = unknowns[j];
    const double value = std::clamp(x[Eigen::Index(j)], u.low, u.high);
    if (u.parameter == "height") {
      p.macro.height = value;
    } else {
      p.measures[u.parameter] = std::clamp(value, -1.0, 1.0);
      if (std::abs(value) > 1) extend(p, start, value > 0 ? u.above : u.below, std::abs(value) - 1, value > 0 ? 1 : -1);
    }
  }
  return p;
}

struct Evaluation {
  TriangleMesh body;
  BodyMeasurements measured;
  Eigen::VectorXd residual;  // m, measured - goal
};

class Problem {
 public:
  Problem(const HumanModel& model, const HumanParameters& start, const std::vector<MeasurementGoal>& goals)
      : model_(model), start_(start), goals_(goals), unknowns_(unknownsFor(goals, start)) {}
  const std::vector<Unknown>& unknowns() const { return unknowns_; }
  const std::vector<MeasurementGoal>& goals() const { return goals_; }
  const HumanParameters& start() const { return start_; }

  // The body at mass s and unknowns x, measured where `goals` need (all goals when null).
  Evaluation evaluate(double s, const Eigen::VectorXd& x, const std::vector<MeasurementGoal>* goals = nullptr) const {
    const std::vector<MeasurementGoal>& g = goals ? *goals : goals_;
    std::vector<std::string> keys;
    for (const MeasurementGoal& goal : g) keys.push_back(goal.key);
    Evaluation e;
    e.body = model_.make(applied(start_, s, unknowns_, x));
    e.measured = measureBody(e.body, keys);
    e.residual.resize(Eigen::Index(g.size()));
    for (size_t i = 0; i < g.size(); ++i) e.residual[Eigen::Index(i)] = e.measured.byName(g[i].key) - g[i].value;
    return e;
  }
  Eigen::VectorXd clamped(Eigen::VectorXd x) const {
    for (size_t j = 0; j < unknowns_.size(); ++j)
      x[Eigen::Index(j)] = std::clamp(x[Eigen::Index(j)], unknowns_[j].low, unknowns_[j].high);
    return x;
  }

 private:
  const HumanModel& model_;
  const HumanParameters& start_;
  const std::vector<MeasurementGoal>& goals_;
  std::vector<Unknown> unknowns_;
};

Eigen::MatrixXd jacobian(const Problem& problem, double s, const Eigen::VectorXd& x, const Eigen::VectorXd& residual) {
  const Eigen::Index n = x.size();
  Eigen::MatrixXd J(residual.size(), n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double step =
        x[j] + kDifferenceStep <= problem.unknowns()[size_t(j)].high ? kDifferenceStep : -kDifferenceStep;  // in range
    Eigen::VectorXd moved = x;
    moved[j] += step;
    J.col(j) = (problem.evaluate(s, moved).residual - residual) / step;
  }
  return J;
}

// The stature alone first (it moves with the height only, and sets the scale every girth
// grows with): secant steps on the macro height, each body's bounds its stature.
void meetStature(const Problem& problem, double s, Eigen::VectorXd& x) {
  const auto& unknowns = problem.unknowns();
  const auto it = std::find_if(unknowns.begin(), unknowns.end(), [](const Unknown& u) { return u.key == "stature"; });
  if (it == unknowns.end()) return;
  const Eigen::Index j = it - unknowns.begin();
  const std::vector<MeasurementGoal> stature = {problem.goals()[size_t(j)]};
  double a = x[j], fa = problem.evaluate(s, x, &stature).residual[0];
  double b = a + (a + kDifferenceStep <= 1.0 ? kDifferenceStep : -kDifferenceStep);
  for (int k = 0; k < 6 && std::abs(fa) > 2e-4; ++k) {
    x[j] = std::clamp(b, it->low, it->high);
    const double fb = problem.evaluate(s, x, &stature).residual[0];
    if (fb == fa) break;
    const double next = b - fb * (b - a) / (fb - fa);
    a = x[j], fa = fb, b = std::clamp(next, it->low, it->high);
    if (b == a) break;
  }
}

// The mass at which the typed girths' errors sum to zero (the measure targets then shape what
// the mass does not: a body of 104 cm waist is a heavier body, not an average one with its
// waist pushed out); an end of the path when even that end leaves them all one way.
double naturalMass(const Problem& problem, const Eigen::VectorXd& x) {
  std::vector<MeasurementGoal> girths;
  for (const MeasurementGoal& goal : problem.goals())
    if (goal.key.ends_with("_girth")) girths.push_back(goal);
  double a = problem.start().macro.weight;
  if (girths.empty()) return a;
  const auto f = [&](double s) { return problem.evaluate(s, x, &girths).residual.sum(); };
  double fa = f(a);
  double b = fa > 0 ? kMassLow : kMassHigh, fb = f(b);
  if ((fa > 0) == (fb > 0)) return b;
  double c = b;
  for (int k = 0; k < 8 && std::abs(b - a) > 0.005; ++k) {
    c = b - fb * (b - a) / (fb - fa);
    const double fc = f(c);
    if (std::abs(fc) < 0.002) break;
    if ((fc > 0) == (fb > 0))
      fa *= 0.5;  // Illinois: the end kept twice in a row weighs half
    else
      a = b, fa = fb;
    b = c, fb = fc;
  }
  return c;
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

double worst(const Evaluation& e) {
  return e.residual.size() ? e.residual.cwiseAbs().maxCoeff() : 0.0;
}

// Gauss-Newton from x, each step halved until the residual shrinks (a landmark moving to
// another level makes the measurements only piecewise smooth); J by Broyden's update after
// each step, anew by differences when a step fails on an updated one.
int solve(const Problem& problem, double s, Eigen::VectorXd& x, Evaluation& e, double aim, int maxIterations) {
  Eigen::MatrixXd J;
  bool fresh = false;
  int iterations = 0;
  for (; iterations < maxIterations && worst(e) > aim; ++iterations) {
    if (J.size() == 0) J = jacobian(problem, s, x, e.residual), fresh = true;
    const Eigen::VectorXd delta = J.colPivHouseholderQr().solve(-e.residual);
    bool moved = false;
    for (double fraction = 1; fraction >= 1.0 / 16 && !moved; fraction *= 0.5) {
      const Eigen::VectorXd next = problem.clamped(x + fraction * delta);
      Evaluation there = problem.evaluate(s, next);
      if (!(there.residual.norm() < e.residual.norm())) continue;
      const Eigen::VectorXd dx = next - x, dr = there.residual - e.residual;
      if (dx.squaredNorm() > 0) J += (dr - J * dx) * dx.transpose() / dx.squaredNorm();
      x = next, e = std::move(there), moved = true;
    }
    if (moved)
      fresh = false;
    else if (fresh)
      break;  // as near as it gets
    else
      J.resize(0, 0);  // the updated J misled: differences anew
  }
  return iterations;
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& measurableKeys() {
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

MeasuredBody makeMeasuredBody(const HumanModel& model, const HumanParameters& start,
                              const std::vector<MeasurementGoal>& goals, const MeasuredBodyOptions& options) {
  const Problem problem(model, start, goals);
  Eigen::VectorXd x = startingPoint(start, problem.unknowns());
  meetStature(problem, start.macro.weight, x);
  const double s = naturalMass(problem, x);
  Evaluation e = problem.evaluate(s, x);
  // aim well inside the tolerance: the measurement's own steps (1 mm levels) stay below it
  MeasuredBody result;
  result.iterations = solve(problem, s, x, e, 0.25 * options.tolerance, options.maxIterations);
  if (worst(e) > options.tolerance) refuse(goals, e);
  result.parameters = applied(start, s, problem.unknowns(), x);
  result.body = std::move(e.body);
  result.achieved = measureBody(result.body);
  return result;
}

}  // namespace figment
