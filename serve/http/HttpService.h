#pragma once
// figment-serve's HTTP side (cpp-httplib): the routes, their headers and errors, the
// in-memory image cache in front of the worker pool, and with --redis the images every
// instance made (serve/workers/SharedImages.h) below it. Every answer but a PNG, the page and
// a 304 is JSON; an unknown path is 404 JSON and reads no file.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "serve/http/ClientRateLimit.h"
#include "serve/http/ImageCache.h"
#include "serve/workers/RedisConnection.h"
#include "serve/workers/RenderJobs.h"
#include "serve/workers/ServeOptions.h"
#include "serve/workers/SharedImages.h"
#include "serve/workers/WorkerPool.h"

namespace httplib {
class Server;
struct Request;
struct Response;
}  // namespace httplib

namespace figment {
class GarmentCatalogue;
}

namespace figment::serve {

class ExchangeServer;

class HttpService {
 public:
  // `program` is this program (started again for each worker in its worker mode). With
  // `options.workers` 0 no worker is started: every request is judged and answered as
  // ever, and every render or fit that would start is refused with 503 (the pool's queue
  // full), which is what tests and the exchange's fuzz target need.
  HttpService(const ServeOptions& options, const std::string& program);
  ~HttpService();

  using Handler = void (HttpService::*)(const httplib::Request&, httplib::Response&);
  // One route: a path as /openapi.json lists it ("{id}": one path segment) and a method
  // (GET answers HEAD too).
  struct Route {
    std::string path;
    std::string method;  // GET or POST
    Handler handle;
  };
  // Every route the service answers: the embedded files, then the API. addRoutes()
  // registers exactly these, and answers 405 with their methods for any other method on
  // their paths; the OpenAPI test compares the document with them.
  static const std::vector<Route>& routes();

  // Binds (port 0: any free one); the port taken, or -1 with `error` set.
  int bind(std::string& error);
  // Serves until stop().
  void run();
  void stop();

  // The requests in `bytes`, as a client on one connection from `remoteAddress` would send
  // them, answered in memory by the server's own code (serve/http/ExchangeServer.h): each
  // answer's bytes. Bind and run are not needed.
  std::vector<std::string> exchange(std::string_view bytes, const std::string& remoteAddress = "127.0.0.1");

 private:
  void addRoutes();
  // 405 with Allow for the methods a known path does not take; what is left is httplib's (404).
  void addRefusals();
  void asset(const httplib::Request& request, httplib::Response& response);
  void health(const httplib::Request& request, httplib::Response& response);
  void catalogue(const httplib::Request& request, httplib::Response& response);
  void render(const httplib::Request& request, httplib::Response& response);
  void fit(const httplib::Request& request, httplib::Response& response);
  // POST /api/render: the render as a background job (202 and its status URL).
  void submitJob(const httplib::Request& request, httplib::Response& response);
  void job(const httplib::Request& request, httplib::Response& response);
  void jobStatus(const std::string& id, httplib::Response& response) const;
  // A worker's answer for `work` (a render or a fit), kept by its kind and ETag `tag` in
  // memory and Redis; false when the response was made already (a refusal or an error).
  bool made(const WorkRequest& work, const std::string& tag, const httplib::Request& request,
            httplib::Response& response, std::shared_ptr<const WorkResult>& result);
  // The answer of `kind` (an image, or a fit's advice) for the quoted ETag `tag` from
  // memory, else from Redis (then kept in memory).
  std::shared_ptr<const std::string> keptAnswer(JobKind kind, const std::string& tag);

  ServeOptions options_;
  std::string build_;  // Digest::buildDigest()
  // The scenes' garment catalogue and its chart; null when it did not read: the Mannequin
  // alone, no fit.
  std::shared_ptr<const GarmentCatalogue> catalogue_;
  std::unique_ptr<WorkerPool> pool_;
  ImageCache images_;
  std::shared_ptr<RedisConnection> redis_;      // null without --redis
  std::unique_ptr<SharedImages> sharedImages_;  // answers in Redis, below images_
  ClientRateLimit rateLimit_;
  std::unique_ptr<ExchangeServer> server_;
  std::unique_ptr<RenderJobs> jobs_;  // last: its threads stop before the pool and caches they use go
};

}  // namespace figment::serve
