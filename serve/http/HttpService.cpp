#include "serve/http/HttpService.h"

#include <httplib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "serve/http/ExchangeServer.h"
#include "serve/http/WebAssets.h"
#include "serve/request/FitRequest.h"
#include "serve/request/MadeBodyChoices.h"
#include "serve/request/RenderRequest.h"
#include "serve/request/ShopperChoices.h"
#include "serve/request/Utf8Text.h"
#include "serve/workers/Digest.h"
#include "serve/workers/RedisStore.h"

namespace figment::serve {

namespace {

constexpr const char* kJson = "application/json";
constexpr int kHttpThreads = 64;  // connections served at once; renders wait in the pool's bounded queue

// JSON text that is UTF-8 whatever the value holds. What an answer echoes of a request goes
// through Utf8Text::shown first; should anything else hold bytes that are not UTF-8, they
// become U+FFFD here rather than an exception (nlohmann's default), which was a 500.
std::string jsonText(const nlohmann::json& body) {
  return body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void sendJson(httplib::Response& response, int status, const nlohmann::json& body) {
  response.status = status;
  response.set_header("Cache-Control", "no-store");
  response.set_content(jsonText(body), kJson);
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

// The regular expression cpp-httplib matches a route's path with: the path's text as it is
// (its '.' escaped), and a "{name}" of the document one path segment.
std::string patternOf(std::string_view path) {
  std::string pattern;
  for (size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '{' && path.find('}', i) != std::string_view::npos) {
      pattern += "([^/]+)";
      i = path.find('}', i);
    } else {
      pattern += (path[i] == '.' ? std::string("\\.") : std::string(1, path[i]));
    }
  }
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
    case 411:
      return "length required";
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

// A path of the route table as the refusals need it.
struct KnownPath {
  std::regex pattern;
  std::set<std::string> methods;  // GET, POST
  std::string allow;              // as the Allow header says it
};

void refuseMethod(httplib::Response& response, const std::string& allow) {
  response.set_header("Allow", allow);
  sendJson(response, 405, {{"error", errorText(405)}, {"allowed", allow}});
}

// Why where a request's body ends is unclear, with the status that says so (400, or 411 for
// a body without a length), or status 0. cpp-httplib 0.11.4 reads a body only for POST, PUT,
// PATCH and DELETE: by the first Content-Length as strtoull reads it ("1e3" is 1); chunked,
// or with no Content-Length until the client closes, both with no bound at all
// (payload_max_length is not applied: 4 MB went into memory either way). What it does not
// read stays on the connection and is read as the next request: behind a proxy that keeps
// its connections to us open (deploy/nginx.conf) that next "request" is smuggled past the
// proxy, and its answer goes to whoever's request the proxy sends next.
std::pair<int, const char*> framingError(const httplib::Request& request) {
  const bool readsBody =
      request.method == "POST" || request.method == "PUT" || request.method == "PATCH" || request.method == "DELETE";
  if (request.has_header("Transfer-Encoding"))
    return readsBody ? std::pair(411, "a chunked body: a body is read to its stated length only")
                     : std::pair(400, "a body on a request that takes none");
  const size_t lengths = request.get_header_value_count("Content-Length");
  if (lengths == 0 && readsBody && request.method != "DELETE")  // httplib takes a DELETE without one as empty
    return {411, "no Content-Length: a body is read to its stated length only"};
  for (size_t i = 0; i < lengths; ++i) {
    const std::string length = request.get_header_value("Content-Length", i);
    if (length.empty() || length.size() > 18 || length.find_first_not_of("0123456789") != std::string::npos ||
        length != request.get_header_value("Content-Length"))
      return {400, "a Content-Length that is not one whole number"};
    if (!readsBody && length.find_first_not_of('0') != std::string::npos)
      return {400, "a body on a request that takes none"};
  }
  return {0, nullptr};
}

// The refusal of a request whose end on its connection is unknown: with "Connection: close",
// for the client and for a proxy (which then takes the connection out of its pool) must not
// send another request on it. cpp-httplib itself reads on; what it answers there no one reads.
void refuseAndClose(httplib::Response& response, int status, const char* error) {
  response.set_header("Connection", "close");
  sendJson(response, status, {{"error", error}});
}

}  // namespace

HttpService::HttpService(const ServeOptions& options, const std::string& program)
    : options_(options),
      build_(Digest::buildDigest()),
      images_(options.imageCacheBytes),
      rateLimit_(options.renderRate, options.renderBurst),
      server_(std::make_unique<ExchangeServer>()) {
  if (!options_.redisUrl.empty()) {
    RedisConnection::Options redis;
    redis.commandTimeout = 0.5;  // s: a request waits no longer on Redis than that, then goes on without it
    redis.log = [](const std::string& line) { std::fprintf(stderr, "figment-serve: %s\n", line.c_str()); };
    redis_ = std::make_shared<RedisConnection>(options_.redisUrl, redis);
    sharedImages_ = std::make_unique<SharedImages>(std::make_shared<RedisStore>(redis_, options_.redisTtl));
  }
  try {
    catalogue_ = MadeBodyChoices::readCatalogue(options_.scenesFolder);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "figment-serve: made bodies and size advice off: %s\n", error.what());
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
      [this](const std::string& canonical) {
        return pool_->ask({JobKind::kRender, canonical});
      },
      [this](const std::string& id, const WorkResult& result) {
        if (!result.keepable()) return;  // a restless or torn drape: rendered again when asked
        images_.store(JobKind::kRender, '"' + id + '"', std::make_shared<const std::string>(result.body));
        if (sharedImages_) sharedImages_->store(JobKind::kRender, id, result.body);
      });
  addRoutes();
}

HttpService::~HttpService() = default;

const std::vector<HttpService::Route>& HttpService::routes() {
  static const std::vector<Route> table = [] {
    std::vector<Route> all;
    for (const WebAsset& asset : webAssets()) all.push_back({std::string(asset.path), "GET", &HttpService::asset});
    const std::vector<Route> api = {
        {"/healthz", "GET", &HttpService::health},    {"/api/catalogue", "GET", &HttpService::catalogue},
        {"/api/render", "GET", &HttpService::render}, {"/api/render", "POST", &HttpService::submitJob},
        {"/api/fit", "GET", &HttpService::fit},       {"/api/jobs/{id}", "GET", &HttpService::job}};
    all.insert(all.end(), api.begin(), api.end());
    return all;
  }();
  return table;
}

void HttpService::addRoutes() {
  for (const Route& route : routes()) {
    const auto handler = [this, handle = route.handle](const httplib::Request& request, httplib::Response& response) {
      (this->*handle)(request, response);
    };
    if (route.method == "GET")
      server_->Get(patternOf(route.path), handler);
    else
      server_->Post(patternOf(route.path), handler);
  }
  addRefusals();
  // Every refusal as JSON, httplib's own (404, 414, ...) included; a handler's JSON stays.
  // httplib's 400 (a head or body it could not read), 413 (a body past the limit, left
  // unread) and 414 (a request line past the limit) leave the connection at an unknown point
  // of the request: it closes, as the framing refusals do.
  server_->set_error_handler([](const httplib::Request&, httplib::Response& response) {
    if (!response.body.empty()) return;
    if (response.status == 400 || response.status == 413 || response.status == 414)
      return refuseAndClose(response, response.status, errorText(response.status));
    sendJson(response, response.status, {{"error", errorText(response.status)}});
  });
  // One Connection field, and no Keep-Alive beside "close": cpp-httplib adds its own from the
  // request alone.
  server_->set_post_routing_handler([](const httplib::Request&, httplib::Response& response) {
    if (response.get_header_value("Connection") != "close") return;
    response.headers.erase("Connection");
    response.headers.erase("Keep-Alive");
    response.set_header("Connection", "close");
  });
  server_->set_exception_handler([](const httplib::Request&, httplib::Response& response, std::exception_ptr) {
    sendJson(response, 500, {{"error", "server error"}});
  });
}

void HttpService::addRefusals() {
  std::map<std::string, std::set<std::string>> taken;  // each path's methods, from the table
  for (const Route& route : routes()) taken[route.path].insert(route.method);
  std::vector<KnownPath> known;
  for (const auto& [path, methods] : taken) {
    std::string allow = methods.count("GET") ? "GET, HEAD" : "";  // httplib answers HEAD as GET
    if (methods.count("POST")) allow += allow.empty() ? "POST" : ", POST";
    const auto refuse = [allow](const httplib::Request&, httplib::Response& response) {
      refuseMethod(response, allow);
    };
    // As handlers, so cpp-httplib reads a refused request's body first (within the payload
    // limit) and the connection goes on at the next request, not inside this one's body.
    const std::string pattern = patternOf(path);
    if (!methods.count("GET")) server_->Get(pattern, refuse);
    if (!methods.count("POST")) server_->Post(pattern, refuse);
    server_->Put(pattern, refuse);
    server_->Patch(pattern, refuse);
    server_->Delete(pattern, refuse);
    server_->Options(pattern, refuse);
    known.push_back({std::regex(pattern), methods, allow});
  }
  // Before routing, and before cpp-httplib reads any body: a request whose body's end is
  // unclear is answered at once and its connection closed (405 still where its method is
  // refused); TRACE and CONNECT, which cpp-httplib has no handlers for (it answered them 400),
  // are judged by the same table.
  server_->set_pre_routing_handler([known](const httplib::Request& request, httplib::Response& response) {
    const auto [status, error] = framingError(request);
    if (status == 0 && request.method != "TRACE" && request.method != "CONNECT")
      return httplib::Server::HandlerResponse::Unhandled;
    const auto path = std::find_if(known.begin(), known.end(),
                                   [&](const KnownPath& p) { return std::regex_match(request.path, p.pattern); });
    if (status != 0) response.set_header("Connection", "close");
    if (path != known.end() && !path->methods.count(request.method == "HEAD" ? "GET" : request.method))
      refuseMethod(response, path->allow);
    else if (status != 0)
      sendJson(response, status, {{"error", error}});
    else
      sendJson(response, 404, {{"error", errorText(404)}});
    return httplib::Server::HandlerResponse::Handled;
  });
}

void HttpService::asset(const httplib::Request& request, httplib::Response& response) {
  const WebAsset* asset = findWebAsset(request.path);
  if (!asset) return sendJson(response, 404, {{"error", errorText(404)}});  // routes() holds only assets' paths
  response.set_header("Cache-Control", "no-cache");
  const std::string type(asset->type);
  response.set_content(std::string(asset->content), type.rfind("text/", 0) == 0 ? type + "; charset=utf-8" : type);
}

void HttpService::catalogue(const httplib::Request&, httplib::Response& response) {
  nlohmann::json catalogue = ShopperChoices::sharedJson();
  catalogue["bodies"] = catalogue_ ? nlohmann::json{"made", "mannequin"} : nlohmann::json{"mannequin"};
  if (catalogue_) catalogue["made"] = MadeBodyChoices::toJson(*catalogue_);
  catalogue["mannequin"] = ShopperChoices::mannequinJson();
  catalogue["limits"] = limitsJson();
  response.set_header("Cache-Control", "public, max-age=300");
  response.set_content(jsonText(catalogue), kJson);
}

void HttpService::health(const httplib::Request&, httplib::Response& response) {
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

// The quoted strong ETag of `work` under build `build`.
std::string tagOf(const WorkRequest& work, const std::string& build) {
  return '"' + Digest().add(work.digestText()).add(build).hex() + '"';
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

bool HttpService::made(const WorkRequest& work, const std::string& tag, const httplib::Request& request,
                       httplib::Response& response, std::shared_ptr<const WorkResult>& result) {
  if (double wait = 0; !rateLimit_.take(request.remote_addr, ClientRateLimit::Clock::now(), wait)) {
    response.set_header("Retry-After", std::to_string(std::max(1, int(std::ceil(wait)))));
    sendJson(response, 429, {{"error", "too many renders from this client; try again"}});
    return false;
  }
  result = pool_->ask(work);
  if (!result) {
    response.set_header("Retry-After", "2");
    sendJson(response, 503, {{"error", "too many renders waiting; try again"}});
    return false;
  }
  if (result->status != 200) {
    const nlohmann::json error = nlohmann::json::parse(result->body, nullptr, false);
    sendJson(response, result->status, error.is_object() ? error : nlohmann::json{{"error", "the render failed"}});
    return false;
  }
  if (!result->keepable()) return true;  // a restless or torn drape is answered, never kept
  images_.store(work.kind, tag, std::make_shared<const std::string>(result->body));
  if (sharedImages_) sharedImages_->store(work.kind, tag.substr(1, tag.size() - 2), result->body);
  return true;
}

void HttpService::render(const httplib::Request& request, httplib::Response& response) {
  const QueryParameters parameters(request.params.begin(), request.params.end());
  auto parsed = RenderRequest::parse(parameters, catalogue_.get());
  if (auto* error = std::get_if<ParameterError>(&parsed)) return sendRefusal(response, *error);
  const WorkRequest work{JobKind::kRender, std::get<RenderRequest>(parsed).canonical()};
  const char* type = std::get<RenderRequest>(parsed).format == "glb" ? "model/gltf-binary" : "image/png";
  const std::string tag = tagOf(work, build_);
  if (notModified(request, response, tag)) return;
  // Only drapes at rest are kept (WorkResult::keepable): a kept picture's drape is at rest.
  if (std::shared_ptr<const std::string> kept = keptAnswer(work.kind, tag))
    return answer(response, tag, *kept, type, true, "rest");
  std::shared_ptr<const WorkResult> result;
  if (made(work, tag, request, response, result))
    answer(response, tag, result->body, type, result->drapeFromCache, result->drape);
}

void HttpService::fit(const httplib::Request& request, httplib::Response& response) {
  if (!catalogue_) return sendJson(response, 503, {{"error", "no garment catalogue: size advice is off"}});
  const QueryParameters parameters(request.params.begin(), request.params.end());
  auto parsed = FitRequest::parse(parameters, *catalogue_);
  if (auto* error = std::get_if<ParameterError>(&parsed)) return sendRefusal(response, *error);
  const WorkRequest work{JobKind::kFit, std::get<FitRequest>(parsed).canonical()};
  const std::string tag = tagOf(work, build_);
  if (notModified(request, response, tag)) return;
  if (std::shared_ptr<const std::string> kept = keptAnswer(work.kind, tag))
    return answer(response, tag, *kept, kJson, true);
  std::shared_ptr<const WorkResult> result;
  if (made(work, tag, request, response, result)) answer(response, tag, result->body, kJson, false);
}

void HttpService::submitJob(const httplib::Request& request, httplib::Response& response) {
  const QueryParameters parameters(request.params.begin(), request.params.end());
  auto parsed = RenderRequest::parse(parameters, catalogue_.get());
  if (auto* error = std::get_if<ParameterError>(&parsed)) return sendRefusal(response, *error);
  const WorkRequest work{JobKind::kRender, std::get<RenderRequest>(parsed).canonical()};
  const std::string tag = tagOf(work, build_);
  const std::string id = tag.substr(1, tag.size() - 2);  // unquoted: a path segment
  const bool kept = keptAnswer(work.kind, tag) != nullptr;
  if (!kept && !jobs_->find(id)) {  // a new job costs a render: the client's rate applies
    if (double wait = 0; !rateLimit_.take(request.remote_addr, ClientRateLimit::Clock::now(), wait)) {
      response.set_header("Retry-After", std::to_string(std::max(1, int(std::ceil(wait)))));
      return sendJson(response, 429, {{"error", "too many renders from this client; try again"}});
    }
  }
  if (!jobs_->submit(id, work.canonical, kept)) {
    response.set_header("Retry-After", "2");
    return sendJson(response, 503, {{"error", "too many renders waiting; try again"}});
  }
  response.set_header("Location", "/api/jobs/" + id);
  jobStatus(id, response);
  response.status = 202;
}

void HttpService::job(const httplib::Request& request, httplib::Response& response) {
  jobStatus(request.matches[1], response);
}

void HttpService::jobStatus(const std::string& id, httplib::Response& response) const {
  const std::optional<RenderJobs::Status> job = jobs_->find(id);
  // The id is the path's segment percent-decoded: any bytes; shown as text.
  if (!job) return sendJson(response, 404, {{"error", "no such job"}, {"id", Utf8Text::shown(id, 64)}});
  nlohmann::json body = {{"status", job->state}, {"result", "/api/render?" + job->canonical}};
  if (!job->error.empty()) body["error"] = job->error;
  sendJson(response, 200, body);
}

std::shared_ptr<const std::string> HttpService::keptAnswer(JobKind kind, const std::string& tag) {
  if (std::shared_ptr<const std::string> kept = images_.find(kind, tag)) return kept;
  if (!sharedImages_) return nullptr;
  std::shared_ptr<const std::string> kept = sharedImages_->find(kind, tag.substr(1, tag.size() - 2));  // unquoted
  if (kept) images_.store(kind, tag, kept);
  return kept;
}

std::vector<std::string> HttpService::exchange(std::string_view bytes, const std::string& remoteAddress) {
  return server_->exchange(bytes, remoteAddress);
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
