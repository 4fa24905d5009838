#include "serve/workers/JobWorker.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "serve/request/MadeBodyChoices.h"
#include "serve/request/RenderRequest.h"
#include "serve/workers/Digest.h"
#include "serve/workers/JobQueue.h"
#include "serve/workers/RedisStore.h"
#include "serve/workers/SharedImages.h"

namespace figment::serve {

namespace {

// A worker's JSON error as one line.
std::string errorLine(const WorkResult& result) {
  const nlohmann::json body = nlohmann::json::parse(result.body, nullptr, false);
  std::string line = body.is_object() ? body.value("error", "") : "";
  if (line.empty()) line = "the render failed";
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  return std::to_string(result.status) + ": " + line;
}

}  // namespace

JobWorker::JobWorker(const ServeOptions& options, const std::string& program, std::string consumer, double claimAfter)
    : options_(options),
      consumer_(std::move(consumer)),
      claimAfter_(claimAfter),
      build_(Digest::buildDigest()),
      pool_(std::make_unique<WorkerPool>(workerPoolOptions(options, program))) {
  try {
    catalogue_ = MadeBodyChoices::readCatalogue(options.scenesFolder);
  } catch (const std::exception& error) {
    log(std::string("made bodies off: ") + error.what());
  }
}

JobWorker::~JobWorker() = default;

void JobWorker::log(const std::string& line) {
  std::lock_guard lock(logMutex_);
  if (line == lastLine_) return;
  lastLine_ = line;
  std::fprintf(stderr, "figment-serve: job worker %s: %s\n", consumer_.c_str(), line.c_str());
}

void JobWorker::run() {
  std::vector<std::thread> threads;
  for (int slot = 0; slot < std::max(1, options_.workers); ++slot) threads.emplace_back([this, slot] { take(slot); });
  for (std::thread& thread : threads) thread.join();
}

void JobWorker::take(int slot) {
  RedisConnection::Options connection;
  connection.log = [this](const std::string& line) { log(line); };
  auto redis = std::make_shared<RedisConnection>(options_.redisUrl, connection);
  const auto store = std::make_shared<RedisStore>(redis, options_.redisTtl);
  const SharedImages images(store);
  JobQueue queue(*redis);
  queue.prepare();
  const std::string name = consumer_ + "/" + std::to_string(slot);
  constexpr double kWait = 1.0;  // s a read waits for a job: how soon stop() is seen
  while (!stopping_) {
    if (std::optional<Job> job = queue.next(name, claimAfter_, kWait)) {
      handle(queue, images, *store, *job);
    } else if (!redis->up()) {
      std::this_thread::sleep_for(std::chrono::duration<double>(kWait));
    }
  }
}

void JobWorker::handle(JobQueue& queue, const SharedImages& images, const RedisStore& store, const Job& job) {
  if (job.request.empty()) {  // an entry added by hand, or one whose fields are gone
    queue.fail(job, "400: the job has no request");
    return;
  }
  auto parsed = RenderRequest::parseCanonical(job.request, catalogue_.get());
  if (const auto* error = std::get_if<ParameterError>(&parsed)) {
    queue.fail(job, "400: " + error->error + (error->parameter.empty() ? "" : " (" + error->parameter + ")"));
    return;
  }
  if (job.deliveries > JobQueue::kMaxDeliveries) {
    queue.fail(job, "given up after " + std::to_string(job.deliveries - 1) +
                        " deliveries: each worker that took it stopped before it was done");
    return;
  }
  const std::string canonical = std::get<RenderRequest>(parsed).canonical();
  const std::string tag = Digest().add(canonical).add(build_).hex();
  if (store.contains(SharedImages::nameOf(JobKind::kRender, tag))) {  // made already (delivered twice, or added again)
    queue.complete(job, tag, false);
    return;
  }
  const std::shared_ptr<const WorkResult> result = pool_->ask({JobKind::kRender, canonical});
  if (!result) return;  // stopping: left pending
  if (result->status == 200 && !result->keepable()) {
    // Only drapes at rest are kept (an instance answers a kept image as one): this one is
    // rendered again when asked, and says how its drape ended (X-Figment-Drape).
    queue.fail(job, "the drape did not come to rest: " + result->drape);
  } else if (result->status == 200) {
    // Acknowledged only once the image is kept: Redis away, the job stays pending.
    if (images.store(JobKind::kRender, tag, result->body)) queue.complete(job, tag, true);
  } else if (result->status == 400 || result->status == 500) {
    queue.fail(job, errorLine(*result));
  }  // 502, 504: the worker died or ran too long; pending, to be taken over and tried again
}

}  // namespace figment::serve
