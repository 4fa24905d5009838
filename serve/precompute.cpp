// figment-precompute: puts render jobs on figment-serve's work queue in Redis and shows
// their progress (docs/deploy.md). Job workers (figment-serve --job-worker) render them
// into the shared cache, where every instance then answers them without a render.
//
//   figment-precompute --redis URL --requests FILE       one request per line (a query string)
//   figment-precompute --redis URL --catalogue [--sex S]... [--body S,B,W,H]... [--pose P]... [--view V]...
//                      [--size WxH]
// Requests are checked against the scenes folder's garment catalogue (--scenes), as
// figment-serve checks them.
//   figment-precompute --redis URL --status [--wait S]
//
// A bad request line or option: one line naming it, exit 2, nothing queued.

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <thread>

#include "io/GarmentCatalogue.h"
#include "serve/request/MadeBodyChoices.h"
#include "serve/workers/JobQueue.h"
#include "serve/workers/PrecomputePlan.h"
#include "serve/workers/RedisConnection.h"

namespace {

using figment::serve::JobProgress;
using figment::serve::JobQueue;
using figment::serve::PrecomputePlan;

struct Options {
  std::string redisUrl;
  std::string scenesFolder = FIGMENT_SCENES_DIR;
  std::string requestsFile;
  bool catalogue = false;
  PrecomputePlan::Grid grid;
  bool status = false;
  double wait = 0;  // s
};

void print(const JobProgress& progress) {
  std::printf("figment-precompute: %ld jobs: %ld done, %ld failed, %ld queued (%ld with a worker); %ld made twice\n",
              progress.added, progress.done, progress.failed, progress.queued, progress.pending, progress.madeTwice);
  for (const auto& [consumer, pending] : progress.consumers)
    std::printf("  worker %s: %ld pending\n", consumer.c_str(), pending);
  for (const auto& [request, error] : progress.failures)
    std::printf("  failed: %s: %s\n", request.c_str(), error.c_str());
}

// The requests the options ask for, or the error line.
std::variant<PrecomputePlan::Requests, std::string> plan(const Options& options) {
  std::unique_ptr<figment::GarmentCatalogue> catalogue;
  try {
    catalogue = std::make_unique<figment::GarmentCatalogue>(
        figment::serve::MadeBodyChoices::cataloguePath(options.scenesFolder));
  } catch (const std::exception& error) {
    return std::string("--scenes: ") + error.what();
  }
  if (options.catalogue) return PrecomputePlan::fromCatalogue(options.grid, *catalogue);
  std::ifstream in(options.requestsFile, std::ios::binary);
  if (!in) return options.requestsFile + ": cannot read";
  return PrecomputePlan::fromLines(std::string(std::istreambuf_iterator<char>(in), {}), options.requestsFile,
                                   catalogue.get());
}

// Prints the progress until nothing is queued or `wait` s have passed; 0 when nothing is
// left queued, 1 when time ran out, 3 when Redis could not be read.
int report(JobQueue& queue, double wait) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait);
  for (;;) {
    std::string error;
    const std::optional<JobProgress> progress = queue.progress(error);
    if (!progress) {
      std::fprintf(stderr, "figment-precompute: %s\n", error.c_str());
      return 3;
    }
    if (progress->queued == 0 || std::chrono::steady_clock::now() >= until) {
      print(*progress);
      return progress->queued == 0 ? 0 : 1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
}

int run(const Options& options) {
  figment::serve::RedisConnection redis(options.redisUrl, {});
  JobQueue queue(redis);
  if (options.catalogue || !options.requestsFile.empty()) {
    auto requests = plan(options);
    if (const auto* error = std::get_if<std::string>(&requests)) {
      std::fprintf(stderr, "figment-precompute: %s\n", error->c_str());
      return 2;
    }
    const PrecomputePlan::Requests& jobs = std::get<PrecomputePlan::Requests>(requests);
    std::string error;
    const long added = queue.add(jobs, error);
    if (added < 0) {
      std::fprintf(stderr, "figment-precompute: %s\n", error.c_str());
      return 3;
    }
    std::printf("figment-precompute: %zu requests, %ld added to the queue (the rest queued or done already)\n",
                jobs.size(), added);
    if (!options.status && options.wait <= 0) return 0;
  }
  return report(queue, options.wait);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"figment-precompute: render jobs on figment-serve's work queue in Redis"};
  app.add_option("--redis", options.redisUrl, "Redis: redis://HOST[:PORT][/DB] or a Unix socket's path")->required();
  auto* requests = app.add_option("--requests", options.requestsFile, "a file of requests, one query string a line");
  auto* catalogue = app.add_flag("--catalogue", options.catalogue, "every style and size of the catalogue");
  requests->excludes(catalogue);
  app.add_option("--scenes", options.scenesFolder,
                 "FIGMENT's scenes folder (its garment catalogue), as figment-serve's");
  app.add_option("--sex", options.grid.sexes, "with --catalogue: female or male (repeatable; default: both)");
  app.add_option("--body", options.grid.bodies, "with --catalogue: STATURE,BUST,WAIST,HIPS in metres (repeatable)");
  app.add_option("--pose", options.grid.poses, "with --catalogue: a made body's pose (repeatable; default: rest)");
  app.add_option("--view", options.grid.views, "with --catalogue: a view, AZ,EL or front... (repeatable)");
  app.add_option("--size", options.grid.size, "with --catalogue: the image's WxH");
  app.add_flag("--status", options.status, "print the queue's progress and failures");
  app.add_option("--wait", options.wait, "seconds to wait for the queue to empty before printing its progress")
      ->check(CLI::Range(0.0, 86400.0));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (std::string error; !figment::serve::RedisConnection::parse(options.redisUrl, error)) {
    std::fprintf(stderr, "figment-precompute: --redis %s\n", error.c_str());
    return 2;
  }
  if (!options.catalogue && options.requestsFile.empty() && !options.status && options.wait <= 0) {
    std::fprintf(stderr, "figment-precompute: nothing to do: give --requests FILE, --catalogue or --status\n");
    return 2;
  }
  return run(options);
}
