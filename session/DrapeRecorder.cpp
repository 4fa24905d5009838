#include "session/DrapeRecorder.h"

#include <cmath>

#include "sim/cloth/ClothSolver.h"

namespace figment::session {

namespace {

// Simulated time is a sum of steps: 0.1 may arrive as 0.0999999999. A frame or sample
// due within this much counts as reached.
constexpr double kTimeSlack = 1e-6;  // s

std::vector<SbVec3f> toFloats(const std::vector<Vec3>& x) {
  std::vector<SbVec3f> out;
  out.reserve(x.size());
  for (const Vec3& p : x) out.emplace_back(float(p.x()), float(p.y()), float(p.z()));
  return out;
}

}  // namespace

DrapeRecorder::DrapeRecorder(std::shared_ptr<DrapeContext> context, std::vector<double> frameTimes, double windSpacing)
    : context_(std::move(context)), frameTimes_(std::move(frameTimes)), windSpacing_(windSpacing) {
  context_->stepObserver = [this](const ClothEngine& engine, const ClothSolver& solver) { observe(engine, solver); };
}

DrapeRecorder::~DrapeRecorder() {
  context_->stepObserver = {};
}

void DrapeRecorder::observe(const ClothEngine& engine, const ClothSolver& solver) {
  // A run's first call comes before its first step: an engine simulating again starts over.
  if (solver.iterations() == 0) records_[&engine] = Record{};
  Record& record = records_[&engine];
  const double t = solver.time();
  if (record.frames.size() < frameTimes_.size()) {
    // Kept every step until the last frame is reached: the run may end at any step,
    // and the frames after its end show its last state.
    record.last = toFloats(solver.positions());
    while (record.frames.size() < frameTimes_.size() && t >= frameTimes_[record.frames.size()] - kTimeSlack)
      record.frames.push_back(record.last);
  }
  if (windSpacing_ > 0.0 && solver.model().wind().blows() && t >= record.nextWindTime - kTimeSlack) {
    const Wind& wind = solver.model().wind();
    record.wind.push_back({t, wind.pressure(t), wind.phase(t), solver.model().totalWindForce(solver.positions(), t)});
    record.nextWindTime = (std::floor(t / windSpacing_ + kTimeSlack) + 1.0) * windSpacing_;
  }
}

bool DrapeRecorder::observed(const ClothEngine& engine) const {
  return records_.count(&engine) > 0;
}

std::vector<SbVec3f> DrapeRecorder::frame(const ClothEngine& engine, size_t k) const {
  const auto found = records_.find(&engine);
  if (found == records_.end()) return {};
  const Record& record = found->second;
  return k < record.frames.size() ? record.frames[k] : record.last;
}

const std::vector<WindSample>& DrapeRecorder::windSamples(const ClothEngine& engine) const {
  static const std::vector<WindSample> none;
  const auto found = records_.find(&engine);
  return found == records_.end() ? none : found->second.wind;
}

}  // namespace figment::session
