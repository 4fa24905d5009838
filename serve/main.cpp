// figment-serve: the virtual mannequin service. A shopper's page at /, and GET
// /api/render?... drawing the default mannequin at the shopper's measurements, in an
// outfit of catalogue garments, as a PNG (docs/service.md).
//
//   figment-serve [--port P] [--workers N] [--cache DIR] [--queue Q] [--time-limit S] [--host H]
//                 [--rate R] [--burst B] [--redis URL]
//   figment-serve --redis URL --job-worker [--consumer NAME] [--claim-after S]   (docs/deploy.md)
//
// Renders run in worker processes: this program again, in its worker mode (--worker,
// given by the server only), each with Coin, OSMesa and a drape context to itself.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "headless/InitHeadless.h"
#include "io/DrapeCache.h"
#include "serve/http/HttpService.h"
#include "serve/workers/FrameChannel.h"
#include "serve/workers/JobWorker.h"
#include "serve/workers/RedisConnection.h"
#include "serve/workers/RenderWorker.h"
#include "serve/workers/WorkerProcess.h"

namespace {

int runWorker(const figment::serve::ServeOptions& options) {
  // Coin's messages one line each on the server's stderr (a ClothEngine's error is left to the
  // answer, which carries it).
  figment::initHeadless("figment-serve: worker: ");
  figment::serve::RenderWorker worker(options.scenesFolder, options.cacheFolder, options.redisUrl, options.redisTtl);
  if (options.adviceThreads > 0) worker.adviceThreads(unsigned(options.adviceThreads));
  if (!worker.startError().empty()) {
    std::fprintf(stderr, "figment-serve: worker: %s\n", worker.startError().c_str());
    return 1;
  }
  worker.serve(figment::serve::FrameChannel(figment::serve::WorkerProcess::kWorkerFd));
  return 0;
}

// SIGINT and SIGTERM stop the server from a thread of their own (sigwait), so the
// workers are stopped and waited for; blocked before any thread starts.
sigset_t blockStopSignals() {
  sigset_t stopSignals;
  sigemptyset(&stopSignals);
  sigaddset(&stopSignals, SIGINT);
  sigaddset(&stopSignals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
  return stopSignals;
}

struct JobOptions {
  bool on = false;
  std::string consumer;   // "": HOST-PID
  double claimAfter = 0;  // s; 0: the time limit and 30 s more
};

int runJobWorker(const figment::serve::ServeOptions& options, JobOptions jobs) {
  const sigset_t stopSignals = blockStopSignals();
  if (jobs.consumer.empty()) {
    char host[256] = "";
    gethostname(host, sizeof host - 1);
    jobs.consumer = std::string(host) + "-" + std::to_string(getpid());
  }
  if (jobs.claimAfter <= 0) jobs.claimAfter = options.timeLimit + 30;
  figment::serve::JobWorker worker(options, "/proc/self/exe", jobs.consumer, jobs.claimAfter);
  std::printf("figment-serve: job worker %s on redis %s (%d workers, jobs taken over after %g s idle)\n",
              jobs.consumer.c_str(), options.redisUrl.c_str(), options.workers, jobs.claimAfter);
  std::fflush(stdout);
  std::thread stopper([&worker, stopSignals] {
    int signal = 0;
    sigwait(&stopSignals, &signal);
    worker.stop();
  });
  worker.run();
  stopper.join();
  return 0;
}

int runServer(const figment::serve::ServeOptions& options) {
  const sigset_t stopSignals = blockStopSignals();
  figment::serve::HttpService service(options, "/proc/self/exe");
  std::string error;
  const int port = service.bind(error);
  if (port < 0) {
    std::fprintf(stderr, "figment-serve: %s\n", error.c_str());
    return 1;
  }
  std::printf("figment-serve: http://%s:%d/ (%d workers, drape cache %s, redis %s)\n", options.host.c_str(), port,
              options.workers, options.cacheFolder.empty() ? "off" : options.cacheFolder.c_str(),
              options.redisUrl.empty() ? "off" : options.redisUrl.c_str());
  std::fflush(stdout);
  std::thread stopper([&service, stopSignals] {
    int signal = 0;
    sigwait(&stopSignals, &signal);
    service.stop();
  });
  service.run();
  pthread_kill(stopper.native_handle(), SIGTERM);  // stopped otherwise: let the stopper go too
  stopper.join();
  return 0;
}

void addOptions(CLI::App& app, figment::serve::ServeOptions& options, JobOptions& jobs, bool& worker) {
  app.add_option("--port", options.port, "TCP port on the host (0: any free one)")->check(CLI::Range(0, 65535));
  app.add_option("--host", options.host, "address to listen on");
  app.add_option("--workers", options.workers, "render worker processes (default: one per core)")
      ->check(CLI::Range(1, 64));
  app.add_option("--cache", options.cacheFolder, "drape cache folder (default: $XDG_CACHE_HOME/figment)");
  app.add_option("--queue", options.queue, "renders waiting at most before 503 (default: 4 per worker)")
      ->check(CLI::Range(1, 10000));
  app.add_option("--time-limit", options.timeLimit, "seconds a render may take")->check(CLI::Range(0.001, 3600.0));
  app.add_option("--rate", options.renderRate, "renders a second per client address (0: no limit)")
      ->check(CLI::Range(0.0, 1e6));
  app.add_option("--burst", options.renderBurst, "renders a client may ask for at once")->check(CLI::Range(1.0, 1e6));
  app.add_option("--scenes", options.scenesFolder, "FIGMENT's scenes folder (the body and patterns)");
  app.add_option("--redis", options.redisUrl,
                 "Redis shared by instances: redis://HOST[:PORT][/DB] or a Unix socket's path (docs/deploy.md)");
  app.add_option("--redis-ttl", options.redisTtl, "seconds a cache entry stays in Redis unread")
      ->check(CLI::Range(1L, 10L * 365 * 24 * 3600));
  app.add_option("--advice-threads", options.adviceThreads,
                 "an advice's sizes draped at once in a worker, each on a thread (default: one per core; 1 where "
                 "every worker is busy)")
      ->check(CLI::Range(1, 64));
  app.add_flag("--job-worker", jobs.on, "take render jobs from the work queue in --redis instead of serving HTTP");
  app.add_option("--consumer", jobs.consumer, "this job worker's name (default: HOST-PID)");
  app.add_option("--claim-after", jobs.claimAfter,
                 "seconds a job stays with a worker before another takes it over (default: the time limit + 30)")
      ->check(CLI::Range(0.001, 86400.0));
  app.add_flag("--worker", worker, "run as a render worker (the server starts these)")->group("");
}

// One line and exit status 2 for options that cannot work together; "" when they can.
std::string optionsError(const figment::serve::ServeOptions& options, const JobOptions& jobs, bool worker) {
  if (std::string error; !options.redisUrl.empty() && !figment::serve::RedisConnection::parse(options.redisUrl, error))
    return "--redis " + error;
  if (!worker && !std::filesystem::is_directory(options.scenesFolder))
    return "--scenes: " + options.scenesFolder + ": no such folder";
  if (jobs.on && options.redisUrl.empty()) return "--job-worker needs --redis";
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  figment::serve::ServeOptions options;
  options.workers = int(std::max(1u, std::thread::hardware_concurrency()));
  options.cacheFolder = figment::DrapeCache::userFolder().string();
  options.scenesFolder = FIGMENT_SCENES_DIR;
  bool worker = false;
  JobOptions jobs;
  CLI::App app{"figment-serve: the virtual mannequin service"};
  addOptions(app, options, jobs, worker);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (const std::string error = optionsError(options, jobs, worker); !error.empty()) {
    std::fprintf(stderr, "figment-serve: %s\n", error.c_str());
    return 2;
  }
  if (worker) return runWorker(options);
  return jobs.on ? runJobWorker(options, jobs) : runServer(options);
}
