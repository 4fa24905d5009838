#include "serve/workers/WorkerPool.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace figment::serve {

struct WorkerPool::Job {
  WorkRequest request;
  std::shared_ptr<const WorkResult> result;  // set once, under the pool's mutex
  std::condition_variable done;
};

namespace {

WorkResult failure(int status, const std::string& error) {
  return {status, nlohmann::json{{"error", error}}.dump(), false, ""};
}

}  // namespace

PoolOptions workerPoolOptions(const ServeOptions& options, const std::string& program) {
  PoolOptions pool;
  pool.program = program;
  pool.arguments = {"--worker", "--scenes", options.scenesFolder, "--cache", options.cacheFolder};
  if (options.adviceThreads > 0)
    pool.arguments.insert(pool.arguments.end(), {"--advice-threads", std::to_string(options.adviceThreads)});
  if (!options.redisUrl.empty())
    pool.arguments.insert(pool.arguments.end(),
                          {"--redis", options.redisUrl, "--redis-ttl", std::to_string(options.redisTtl)});
  pool.workers = std::max(0, options.workers);  // 0: none (the command line asks for 1 or more)
  pool.queue = options.queue > 0 ? options.queue : 4 * pool.workers;
  pool.timeLimit = options.timeLimit;
  return pool;
}

WorkerPool::WorkerPool(PoolOptions options) : options_(std::move(options)) {
  for (int slot = 0; slot < options_.workers; ++slot) threads_.emplace_back([this, slot] { run(slot); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  queued_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

std::shared_ptr<const WorkResult> WorkerPool::ask(const WorkRequest& request) {
  std::unique_lock lock(mutex_);
  std::shared_ptr<Job> job;
  if (auto it = inFlight_.find(request); it != inFlight_.end()) {
    job = it->second;  // single flight: the same picture is being made
  } else {
    // A pool without workers takes nothing: no one would ever answer it.
    if (options_.workers == 0 || int(queue_.size()) >= options_.queue || stopping_) return nullptr;
    job = std::make_shared<Job>();
    job->request = request;
    queue_.push_back(job);
    inFlight_[request] = job;
    queued_.notify_one();
  }
  // The worker's time limit bounds this wait: its thread always finishes the job.
  ++waiting_;
  job->done.wait(lock, [&job] { return job->result != nullptr; });
  --waiting_;
  return job->result;
}

WorkerPool::Load WorkerPool::load() const {
  std::lock_guard lock(mutex_);
  return {options_.workers, busy_, int(queue_.size()), waiting_, restarts_};
}

std::shared_ptr<WorkerPool::Job> WorkerPool::next() {
  std::unique_lock lock(mutex_);
  queued_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
  if (stopping_) return nullptr;
  std::shared_ptr<Job> job = queue_.front();
  queue_.pop_front();
  ++busy_;
  return job;
}

void WorkerPool::finish(const std::shared_ptr<Job>& job, WorkResult result) {
  std::lock_guard lock(mutex_);
  --busy_;
  job->result = std::make_shared<const WorkResult>(std::move(result));
  inFlight_.erase(job->request);
  job->done.notify_all();
}

void WorkerPool::run(int) {
  WorkerProcess worker(options_.program, options_.arguments);
  worker.start();  // at once, so the first request finds it ready
  while (std::shared_ptr<Job> job = next()) {
    if (!worker.running()) worker.start();
    finish(job, makeOn(worker, job->request));
  }
  // Jobs left at shutdown are answered, so no request thread waits forever.
  std::lock_guard lock(mutex_);
  for (const std::shared_ptr<Job>& job : queue_) {
    job->result = std::make_shared<const WorkResult>(failure(503, "the server is stopping"));
    job->done.notify_all();
  }
  queue_.clear();
}

WorkResult WorkerPool::makeOn(WorkerProcess& worker, const WorkRequest& request) {
  const auto deadline =
      FrameChannel::Clock::now() + std::chrono::milliseconds(static_cast<long long>(options_.timeLimit * 1000.0));
  std::string header, body;
  // Two frames: the kind, then the request's text (RenderWorker::serve reads them so).
  const bool sent =
      worker.channel().send(std::string(jobKindName(request.kind))) && worker.channel().send(request.canonical);
  FrameChannel::Result r = sent ? FrameChannel::Result::kOk : FrameChannel::Result::kClosed;
  if (r == FrameChannel::Result::kOk) r = worker.channel().receive(header, deadline);
  if (r == FrameChannel::Result::kOk) r = worker.channel().receive(body, deadline);
  if (r != FrameChannel::Result::kOk) {
    // Dead or past its time: this request fails, the worker is replaced for the next.
    worker.stop();
    {
      std::lock_guard lock(mutex_);
      ++restarts_;
    }
    worker.start();
    return r == FrameChannel::Result::kTimedOut ? failure(504, "the render took longer than the time limit")
                                                : failure(502, "the worker rendering this request stopped");
  }
  const nlohmann::json parsed = nlohmann::json::parse(header, nullptr, false);
  if (!parsed.is_object()) return failure(500, "the worker's answer did not read");
  return {parsed.value("status", 500), std::move(body), parsed.value("drapeCache", "") == "hit",
          parsed.value("drape", "")};
}

}  // namespace figment::serve
