#pragma once
// figment-serve's HTTP side (cpp-httplib): the routes, their headers and errors, the
// in-memory image cache in front of the worker pool, and with --redis the images every
// instance made (serve/SharedImages.h) below it. Every answer but a PNG, the page and
// a 304 is JSON; an unknown path is 404 JSON and reads no file.

#include <memory>
#include <string>
#include <vector>

#include "serve/ClientRateLimit.h"
#include "serve/ImageCache.h"
#include "serve/RedisConnection.h"
#include "serve/RenderJobs.h"
#include "serve/ServeOptions.h"
#include "serve/SharedImages.h"
#include "serve/WorkerPool.h"
#include "sim/garment/SizeChart.h"

namespace httplib {
class Server;
struct Request;
struct Response;
}  // namespace httplib

namespace figment::serve {

class HttpService {
 public:
  // `program` is this program (started again for each worker in its worker mode).
  HttpService(const ServeOptions& options, const std::string& program);
  ~HttpService();

  // Binds (port 0: any free one); the port taken, or -1 with `error` set.
  int bind(std::string& error);
  // Serves until stop().
  void run();
  void stop();

  // Every path the service answers, as /openapi.json lists them.
  static const std::vector<std::string>& routes();

 private:
  void addRoutes();
  void render(const httplib::Request& request, httplib::Response& response);
  void fit(const httplib::Request& request, httplib::Response& response);
  // POST /api/render: the render as a background job (202 and its status URL).
  void submitJob(const httplib::Request& request, httplib::Response& response);
  void jobStatus(const std::string& id, httplib::Response& response) const;
  // A worker's answer for `canonical` (a render or a fit), kept by its ETag `tag` in memory
  // and Redis; false when the response was made already (a refusal or an error).
  bool made(const std::string& canonical, const std::string& tag, const httplib::Request& request,
            httplib::Response& response, std::shared_ptr<const RenderResult>& result);
  void health(httplib::Response& response) const;
  // The image for the quoted ETag `tag` from memory, else from Redis (then kept in memory).
  std::shared_ptr<const std::string> keptImage(const std::string& tag);

  ServeOptions options_;
  std::string build_;                 // Digest::buildDigest()
  std::unique_ptr<SizeChart> chart_;  // null when the scenes' size chart did not read: no fit
  std::unique_ptr<WorkerPool> pool_;
  ImageCache images_;
  std::shared_ptr<RedisConnection> redis_;      // null without --redis
  std::unique_ptr<SharedImages> sharedImages_;  // images in Redis, below images_
  ClientRateLimit rateLimit_;
  std::unique_ptr<httplib::Server> server_;
  std::unique_ptr<RenderJobs> jobs_;  // last: its threads stop before the pool and caches they use go
};

}  // namespace figment::serve
