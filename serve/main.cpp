// figment-serve: the virtual mannequin service. A shopper's page at /, and GET
// /api/render?... drawing the default mannequin at the shopper's measurements, in an
// outfit of catalogue garments, as a PNG (docs/service.md).
//
//   figment-serve [--port P] [--workers N] [--cache DIR] [--queue Q] [--time-limit S] [--host H]
//                 [--rate R] [--burst B]
//
// Renders run in worker processes: this program again, in its worker mode (--worker,
// given by the server only), each with Coin, OSMesa and a drape context to itself.

#include <Inventor/SoDB.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "headless/OsmesaForCoin.h"
#include "io/DrapeCache.h"
#include "nodes/Init.h"
#include "serve/FrameChannel.h"
#include "serve/HttpService.h"
#include "serve/RenderWorker.h"
#include "serve/WorkerProcess.h"

namespace {

// Coin's messages in a worker: one line each on the server's stderr, without the noise of
// a headless program (Coin asks GLX about a context OSMesa made) or a ClothEngine's error
// (the answer carries it).
void onCoinMessage(const SoError* error, void*) {
  std::string text = error->getDebugString().getString();
  if (text.find("glxglue_isdirect") != std::string::npos || text.find("ClothEngine::evaluate") != std::string::npos)
    return;
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "figment-serve: worker: %s\n", text.c_str());
}

int runWorker(const figment::serve::ServeOptions& options) {
  figment::useOsmesaForCoin();
  SoDB::init();
  SoDebugError::setHandlerCallback(onCoinMessage, nullptr);
  SoReadError::setHandlerCallback(onCoinMessage, nullptr);
  figment::init();
  figment::serve::RenderWorker worker(options.scenesFolder, options.cacheFolder);
  if (!worker.startError().empty()) {
    std::fprintf(stderr, "figment-serve: worker: %s\n", worker.startError().c_str());
    return 1;
  }
  worker.serve(figment::serve::FrameChannel(figment::serve::WorkerProcess::kWorkerFd));
  return 0;
}

int runServer(const figment::serve::ServeOptions& options) {
  // SIGINT and SIGTERM stop the server from a thread of their own (sigwait), so the
  // workers are stopped and waited for; blocked here, before any thread starts.
  sigset_t stopSignals;
  sigemptyset(&stopSignals);
  sigaddset(&stopSignals, SIGINT);
  sigaddset(&stopSignals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
  figment::serve::HttpService service(options, "/proc/self/exe");
  std::string error;
  const int port = service.bind(error);
  if (port < 0) {
    std::fprintf(stderr, "figment-serve: %s\n", error.c_str());
    return 1;
  }
  std::printf("figment-serve: http://%s:%d/ (%d workers, drape cache %s)\n", options.host.c_str(), port,
              options.workers, options.cacheFolder.empty() ? "off" : options.cacheFolder.c_str());
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

}  // namespace

int main(int argc, char** argv) {
  figment::serve::ServeOptions options;
  options.workers = int(std::max(1u, std::thread::hardware_concurrency()));
  options.cacheFolder = figment::DrapeCache::userFolder().string();
  options.scenesFolder = FIGMENT_SCENES_DIR;
  bool worker = false;
  CLI::App app{"figment-serve: the virtual mannequin service"};
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
  app.add_flag("--worker", worker, "run as a render worker (the server starts these)")->group("");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (!worker && !std::filesystem::is_directory(options.scenesFolder)) {
    std::fprintf(stderr, "figment-serve: --scenes: %s: no such folder\n", options.scenesFolder.c_str());
    return 2;
  }
  return worker ? runWorker(options) : runServer(options);
}
