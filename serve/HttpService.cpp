#include "serve/HttpService.h"

#include <httplib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "io/SizeChartFile.h"
#include "serve/Catalogue.h"
#include "serve/Digest.h"
#include "serve/FitRequest.h"
#include "serve/RedisStore.h"
#include "serve/RenderRequest.h"
#include "serve/WebAssets.h"

namespace figment::serve {

namespace {

constexpr const char* kJson = "application/json";
constexpr int kHttpThreads = 64;  // connections served at once; renders wait in the pool's bounded queue

void sendJson(httplib::Response& response, int status, const nlohmann::json& body) {
  response.status = status;
  response.set_header("Cache-Control", "no-store");
  response.set_content(body.dump(), kJson);
}

// Whether If-None-Match names `tag` (weak comparison, as RFC 9110 says for it).
bool matches(const std::string& ifNoneMatch, const std::string& tag) {
  size_t start = 0;
  while (start < ifNoneMatch.size()) {
    const size_t comma = std::min(ifNoneMatch.find(',', start), ifNoneMatch.size());
    std::string item = ifNoneMatch.substr(start, comma - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (item.rfind("W/", 0) == 0) item.erase(0, 2);
    if (item == tag || item == "*") return true;
    start = comma + 1;
  }
  return false;
}

std::string regexFor(std::string_view path) {
  std::string pattern;
  for (char c : path) pattern += (c == '.' ? std::string("\\.") : std::string(1, c));
  return pattern;
}

nlohmann::json limitsJson() {
  return {{"imageSide", {RequestLimits::kMinSide, RequestLimits::kMaxSide}},
          {"imagePixels", RequestLimits::kMaxPixels},
          {"garments", RequestLimits::kMaxGarments},
          {"parameters", RequestLimits::kMaxParameters},
          {"valueBytes", RequestLimits::kMaxValueLength},
          {"view", {{"azimuth", {-360, 360}}, {"elevation", {-60, 80}}}}};
}

const char* errorText(int status) {
  switch (status) {
    case 404:
      return "no such path";
    case 405:
      return "method not allowed";
    case 413:
      return "request too large";
    case 414:
      return "URL too long";
    case 429:
      return "too many requests";
    case 431:
      return "headers too large";
    default:
      return status >= 500 ? "server error" : "bad request";
  }
}

}  // namespace

HttpService::HttpService(const ServeOptions& options, const std::string& program)
    : options_(options),
      build_(Digest::buildDigest()),
      images_(options.imageCacheBytes),
      rateLimit_(options.renderRate, options.renderBurst),
      server_(std::make_unique<httplib::Server>()) {
  if (!options_.redisUrl.empty()) {
    RedisConnection::Options redis;
    redis.commandTimeout = 0.5;  // s: a request waits no longer on Redis than that, then goes on without it
    redis.log = [](const std::string& line) { std::fprintf(stderr, "figment-serve: %s\n", line.c_str()); };
    redis_ = std::make_shared<RedisConnection>(options_.redisUrl, redis);
    sharedImages_ = std::make_unique<SharedImages>(std::make_shared<RedisStore>(redis_, options_.redisTtl));
  }
  try {
    chart_ = std::make_unique<SizeChart>(readSizeChart(FitRequest::chartPath(options_.scenesFolder)));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "figment-serve: size advice off: %s\n", error.what());
  }
  pool_ = std::make_unique<WorkerPool>(workerPoolOptions(options_, program));
  server_->new_task_queue = [] { return new httplib::ThreadPool(kHttpThreads); };
  server_->set_keep_alive_max_count(1000);
  // cpp-httplib writes the headers and the body in two sends. With Nagle's algorithm on, a
  // body shorter than a segment (a 58 kB PNG on loopback's 64 kB) waited for the client's
  // delayed ACK of the headers: 44 ms on every keep-alive request (22 a second on one
  // connection); sometimes, for larger bodies, the cached image's 44 ms p99.
  server_->set_tcp_nodelay(true);
  server_->set_payload_max_length(8192);  // only POST /api/render's form of parameters has a body
  const PoolOptions poolOptions = workerPoolOptions(options_, program);
  jobs_ = std::make_unique<RenderJobs>(
      RenderJobs::Options{poolOptions.workers, poolOptions.queue, 1024},
      [this](const std::string& canonical) { return pool_->render(canonical); },
      [this](const std::string& id, const RenderResult& result) {
        if (!result.keepable()) return;  // a restless or torn drape: rendered again when asked
        images_.store('"' + id + '"', std::make_shared<const std::string>(result.body));
        if (sharedImages_) sharedImages_->store(id, result.body);
      });
  addRoutes();
}

HttpService::~HttpService() = default;

const std::vector<std::string>& HttpService::routes() {
  static const std::vector<std::string> paths = {"/",           "/app.js",       "/style.css",
                                                 "/healthz",    "/openapi.json", "/api/catalogue",
                                                 "/api/render", "/api/fit",      "/api/jobs/{id}"};
  return paths;
}

void HttpService::addRoutes() {
  for (const WebAsset& asset : webAssets())
    server_->Get(regexFor(asset.path), [&asset](const httplib::Request&, httplib::Response& response) {
      response.set_header("Cache-Control", "no-cache");
      const std::string type(asset.type);
      response.set_content(std::string(asset.content), type.rfind("text/", 0) == 0 ? type + "; charset=utf-8" : type);
    });
  server_->Get("/healthz", [this](const httplib::Request&, httplib::Response& response) { health(response); });
  server_->Get("/api/catalogue", [this](const httplib::Request&, httplib::Response& response) {
    nlohmann::json catalogue = Catalogue::toJson();
    catalogue["limits"] = limitsJson();
    if (chart_) catalogue["fit"] = FitRequest::catalogueJson(*chart_);
    response.set_header("Cache-Control", "public, max-age=300");
    response.set_content(catalogue.dump(), kJson);
  });
  server_->Get("/api/render",
               [this](const httplib::Request& request, httplib::Response& response) { render(request, response); });
  server_->Post("/api/render",
                [this](const httplib::Request& request, httplib::Response& response) { submitJob(request, response); });
  server_->Get("/api/jobs/([^/]+)", [this](const httplib::Request& request, httplib::Response& response) {
    jobStatus(request.matches[1], response);
  });
  server_->Get("/api/fit",
               [this](const httplib::Request& request, httplib::Response& response) { fit(request, response); });
  // Every refusal as JSON, httplib's own (404, 414, ...) included; a handler's JSON stays.
  server_->set_error_handler([](const httplib::Request&, httplib::Response& response) {
    if (response.body.empty()) sendJson(response, response.status, {{"error", errorText(response.status)}});
  });
  server_->set_exception_handler([](const httplib::Request&, httplib::Response& response, std::exception_ptr) {
    sendJson(response, 500, {{"error", "server error"}});
  });
}

void HttpService::health(httplib::Response& response) const {
  const WorkerPool::Load load = pool_->load();
  sendJson(response, 200,
           {{"status", "ok"},
            {"workers", load.workers},
            {"busy", load.busy},
            {"queued", load.queued},
            {"restarts", load.restarts},
            {"imageCacheBytes", images_.bytes()},
            {"redis", !redis_           ? "off"
                      : redis_->check() ? "up"
                                        : "down"}});
}

namespace {

void sendRefusal(httplib::Response& response, const ParameterError& error) {
  sendJson(
      response, 400,
      {{"error", error.error}, {"parameter", error.parameter}, {"value", error.value}, {"accepted", error.accepted}});
}

// The quoted strong ETag of `canonical` under build `build`.
std::string tagOf(const std::string& canonical, const std::string& build) {
  return '"' + Digest().add(canonical).add(build).hex() + '"';
}

// 304 when the client holds `tag` already.
bool notModified(const httplib::Request& request, httplib::Response& response, const std::string& tag) {
  if (!matches(request.get_header_value("If-None-Match"), tag)) return false;
  response.status = 304;  // the tag names the answer: the client has it
  response.set_header("ETag", tag);
  response.set_header("Cache-Control", "public, max-age=86400");
  return true;
}

// `drape`: a render's X-Figment-Drape (rest, restless, torn); "" for a fit's answer.
void answer(httplib::Response& response, const std::string& tag, const std::string& bytes, const char* type, bool hit,
            const std::string& drape = "") {
  response.set_header("ETag", tag);
  response.set_header("Cache-Control", "public, max-age=86400");
  response.set_header("X-Figment-Cache", hit ? "hit" : "miss");
  if (!drape.empty()) response.set_header("X-Figment-Drape", drape);
  response.set_content(bytes, type);
}

}  // namespace

bool HttpService::made(const std::string& canonical, const std::string& tag, const httplib::Request& request,
                       httplib::Response& response, std::shared_ptr<const RenderResult>& result) {
  if (double wait = 0; !rateLimit_.take(request.remote_addr, ClientRateLimit::Clock::now(), wait)) {
    response.set_header("Retry-After", std::to_string(std::max(1, int(std::ceil(wait)))));
    sendJson(response, 429, {{"error", "too many renders from this client; try again"}});
    return false;
  }
  result = pool_->render(canonical);
  if (!result) {
    response.set_header("Retry-After", "2");
    sendJson(response, 503, {{"error", "too many renders waiting; try again"}});
    return false;
  }
  if (result->status != 200) {
    sendJson(response, result->status, nlohmann::json::parse(result->body, nullptr, false));
    return false;
  }
  if (!result->keepable()) return true;  // a restless or torn drape is answered, never kept
  images_.store(tag, std::make_shared<const std::string>(result->body));
  if (sharedImages_) sharedImages_->store(tag.substr(1, tag.size() - 2), result->body);
  return true;
}

void HttpService::render(const httplib::Request& request, httplib::Response& response) {
  const RenderRequest::Parameters parameters(request.params.begin(), request.params.end());
  auto parsed = RenderRequest::parse(parameters, chart_.get());
  if (auto* error = std::get_if<ParameterError>(&parsed)) return sendRefusal(response, *error);
  const std::string canonical = std::get<RenderRequest>(parsed).canonical();
  const char* type = std::get<RenderRequest>(parsed).format == "glb" ? "model/gltf-binary" : "image/png";
  const std::string tag = tagOf(canonical, build_);
  if (notModified(request, response, tag)) return;
  // Only drapes at rest are kept (RenderResult::keepable): a kept picture's drape is at rest.
  if (std::shared_ptr<const std::string> kept = keptImage(tag)) return answer(response, tag, *kept, type, true, "rest");
  std::shared_ptr<const RenderResult> result;
  if (made(canonical, tag, request, response, result))
    answer(response, tag, result->body, type, result->drapeFromCache, result->drape);
}

void HttpService::fit(const httplib::Request& request, httplib::Response& response) {
  if (!chart_) return sendJson(response, 503, {{"error", "no size chart: size advice is off"}});
  const RenderRequest::Parameters parameters(request.params.begin(), request.params.end());
  auto parsed = FitRequest::parse(parameters, *chart_);
  if (auto* error = std::get_if<ParameterError>(&parsed)) return sendRefusal(response, *error);
  const std::string canonical = std::get<FitRequest>(parsed).canonical();
  const std::string tag = tagOf(canonical, build_);
  if (notModified(request, response, tag)) return;
  if (std::shared_ptr<const std::string> kept = keptImage(tag)) return answer(response, tag, *kept, kJson, true);
  std::shared_ptr<const RenderResult> result;
  if (made(canonical, tag, request, response, result)) answer(response, tag, result->body, kJson, false);
}

void HttpService::submitJob(const httplib::Request& request, httplib::Response& response) {
  const RenderRequest::Parameters parameters(request.params.begin(), request.params.end());
  auto parsed = RenderRequest::parse(parameters, chart_.get());
  if (auto* error = std::get_if<ParameterError>(&parsed)) return sendRefusal(response, *error);
  const std::string canonical = std::get<RenderRequest>(parsed).canonical();
  const std::string tag = tagOf(canonical, build_);
  const std::string id = tag.substr(1, tag.size() - 2);  // unquoted: a path segment
  const bool kept = keptImage(tag) != nullptr;
  if (!kept && !jobs_->find(id)) {  // a new job costs a render: the client's rate applies
    if (double wait = 0; !rateLimit_.take(request.remote_addr, ClientRateLimit::Clock::now(), wait)) {
      response.set_header("Retry-After", std::to_string(std::max(1, int(std::ceil(wait)))));
      return sendJson(response, 429, {{"error", "too many renders from this client; try again"}});
    }
  }
  if (!jobs_->submit(id, canonical, kept)) {
    response.set_header("Retry-After", "2");
    return sendJson(response, 503, {{"error", "too many renders waiting; try again"}});
  }
  response.set_header("Location", "/api/jobs/" + id);
  jobStatus(id, response);
  response.status = 202;
}

void HttpService::jobStatus(const std::string& id, httplib::Response& response) const {
  const std::optional<RenderJobs::Status> job = jobs_->find(id);
  if (!job) return sendJson(response, 404, {{"error", "no such job"}, {"id", utf8Prefix(id, 64)}});
  nlohmann::json body = {{"status", job->state}, {"result", "/api/render?" + job->canonical}};
  if (!job->error.empty()) body["error"] = job->error;
  sendJson(response, 200, body);
}

std::shared_ptr<const std::string> HttpService::keptImage(const std::string& tag) {
  if (std::shared_ptr<const std::string> image = images_.find(tag)) return image;
  if (!sharedImages_) return nullptr;
  std::shared_ptr<const std::string> image = sharedImages_->find(tag.substr(1, tag.size() - 2));  // unquoted
  if (image) images_.store(tag, image);
  return image;
}

int HttpService::bind(std::string& error) {
  const int port = options_.port == 0 ? server_->bind_to_any_port(options_.host)
                                      : (server_->bind_to_port(options_.host, options_.port) ? options_.port : -1);
  if (port < 0) error = "cannot listen on " + options_.host + ":" + std::to_string(options_.port);
  return port;
}

void HttpService::run() {
  server_->listen_after_bind();
}

void HttpService::stop() {
  server_->stop();
}

}  // namespace figment::serve
