#include "serve/workers/RenderJobs.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace figment::serve {

namespace {

// The one-line error of a failed render (the worker's JSON error, else its status).
std::string errorOf(const std::shared_ptr<const WorkResult>& result) {
  if (!result) return "too many renders waiting; try again";
  const nlohmann::json body = nlohmann::json::parse(result->body, nullptr, false);
  if (body.is_object() && body.contains("error") && body["error"].is_string()) return body["error"];
  return "render failed with status " + std::to_string(result->status);
}

}  // namespace

RenderJobs::RenderJobs(Options options, Render render, Keep keep)
    : options_(options), render_(std::move(render)), keep_(std::move(keep)) {
  for (int i = 0; i < std::max(1, options_.threads); ++i) threads_.emplace_back([this] { run(); });
}

RenderJobs::~RenderJobs() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  queued_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

bool RenderJobs::submit(const std::string& id, const std::string& canonical, bool done) {
  std::lock_guard lock(mutex_);
  auto known = jobs_.find(id);
  if (known != jobs_.end() && known->second.state != "failed") return true;  // the same job
  if (!done && queue_.size() >= size_t(std::max(0, options_.waiting))) return false;
  if (known == jobs_.end()) {
    forgetOldest();
    order_.push_back(id);
  }
  jobs_[id] = Status{done ? "done" : "queued", "", canonical};
  if (!done) {
    queue_.push_back(id);
    queued_.notify_one();
  }
  return true;
}

std::optional<RenderJobs::Status> RenderJobs::find(const std::string& id) const {
  std::lock_guard lock(mutex_);
  auto job = jobs_.find(id);
  if (job == jobs_.end()) return std::nullopt;
  return job->second;
}

void RenderJobs::forgetOldest() {
  // Unfinished jobs are few (threads + waiting), so a finished one is found unless the bound is tiny.
  while (jobs_.size() >= std::max<size_t>(1, options_.kept)) {
    auto finished = std::find_if(order_.begin(), order_.end(), [this](const std::string& id) {
      const std::string& state = jobs_.at(id).state;
      return state == "done" || state == "failed";
    });
    if (finished == order_.end()) return;
    jobs_.erase(*finished);
    order_.erase(finished);
  }
}

void RenderJobs::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    queued_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (stopping_) return;
    const std::string id = queue_.front();
    queue_.pop_front();
    Status& job = jobs_.at(id);  // queued jobs are never forgotten
    job.state = "running";
    const std::string canonical = job.canonical;
    lock.unlock();
    std::shared_ptr<const WorkResult> result = render_(canonical);
    const bool made = result && result->status == 200;
    if (made) keep_(id, *result);
    lock.lock();
    Status& finished = jobs_.at(id);  // running jobs are never forgotten either
    finished.state = made ? "done" : "failed";
    finished.error = made ? "" : errorOf(result);
  }
}

}  // namespace figment::serve
