// The OpenAPI document kept beside the code lists every route the service answers (its
// table, which addRoutes() registers), and nothing else; every route but the API's own is
// an embedded file. Then whole exchanges in memory (HttpService::exchange) with a service
// of no workers, so nothing renders: a query or job id that is not UTF-8 is refused naming
// it as escaped text, a method a known path does not take is 405 with Allow, an unknown path
// 404 whatever the method; every answer well formed, every JSON body UTF-8 that parses.

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "serve/http/HttpService.h"
#include "serve/http/WebAssets.h"
#include "support/HttpAnswer.h"

using namespace figment::serve;
using figment::test::HttpAnswer;

namespace {

const char* const kMethods[] = {"get", "put", "post", "delete", "options", "head", "patch", "trace"};

std::string upper(std::string text) {
  for (char& c : text) c = char(std::toupper((unsigned char)c));
  return text;
}

}  // namespace

TEST(HttpService, TheOpenApiDocumentListsEveryRouteAndMethod) {
  const WebAsset* document = findWebAsset("/openapi.json");
  ASSERT_NE(document, nullptr);
  const nlohmann::json json = nlohmann::json::parse(document->content);
  EXPECT_EQ(json["openapi"].get<std::string>().substr(0, 2), "3.");
  std::set<std::pair<std::string, std::string>> listed;  // (path, METHOD)
  for (const auto& [path, item] : json["paths"].items())
    for (const char* method : kMethods)
      if (item.contains(method)) listed.emplace(path, upper(method));
  std::set<std::pair<std::string, std::string>> served;
  for (const HttpService::Route& route : HttpService::routes()) served.emplace(route.path, route.method);
  ASSERT_FALSE(served.empty());
  EXPECT_EQ(listed, served);
}

TEST(HttpService, EveryEmbeddedFileIsARoute) {
  std::set<std::string> routes;
  for (const HttpService::Route& route : HttpService::routes()) routes.insert(route.path);
  ASSERT_FALSE(webAssets().empty());
  for (const WebAsset& asset : webAssets()) {
    EXPECT_TRUE(routes.count(std::string(asset.path))) << asset.path;
    EXPECT_FALSE(asset.content.empty()) << asset.path;
  }
  EXPECT_EQ(findWebAsset("/../openapi.json"), nullptr);  // exact paths only
}

class HttpServiceExchange : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ServeOptions options;
    options.workers = 0;  // no render starts: a valid render is refused 503
    options.renderRate = 0;
    options.scenesFolder = FIGMENT_SOURCE_DIR "/scenes";  // its size chart: /api/fit judges requests
    service_ = std::make_unique<HttpService>(options, "");
  }
  static void TearDownTestSuite() { service_.reset(); }

  // The one answer to `request`, read and checked for form.
  static HttpAnswer ask(const std::string& request) {
    const std::vector<std::string> answers = service_->exchange(request);
    HttpAnswer answer;
    EXPECT_EQ(answers.size(), 1u) << request;
    if (answers.empty()) return answer;
    EXPECT_EQ(figment::test::readAnswer(answers[0], answer), "") << request;
    return answer;
  }
  // Its JSON body: the type says so, and it parses (nlohmann refuses text that is not UTF-8).
  static nlohmann::json json(const HttpAnswer& answer) {
    EXPECT_EQ(answer.header("Content-Type"), "application/json");
    const nlohmann::json body = nlohmann::json::parse(answer.body, nullptr, false);
    EXPECT_TRUE(body.is_object()) << answer.body;
    return body.is_object() ? body : nlohmann::json::object();
  }
  static std::string get(const std::string& target) { return "GET " + target + " HTTP/1.1\r\nHost: t\r\n\r\n"; }
  static std::string post(const std::string& target, const std::string& form) {
    return "POST " + target + " HTTP/1.1\r\nHost: t\r\nContent-Type: application/x-www-form-urlencoded\r\n" +
           "Content-Length: " + std::to_string(form.size()) + "\r\n\r\n" + form;
  }

  static std::unique_ptr<HttpService> service_;
};

std::unique_ptr<HttpService> HttpServiceExchange::service_;

TEST_F(HttpServiceExchange, AQueryThatIsNotUtf8IsRefusedNamingTheParameter) {
  struct Case {
    std::string request, parameter, value;
  };
  const Case cases[] = {
      {get("/api/render?stature=%ff"), "stature", "%FF"},
      {get("/api/render?size=160x200&outfit=dress:%c3%28"), "outfit", "dress:%C3("},
      {get("/api/render?%c0%80=1"), "%C0%80", "1"},     // an overlong NUL as the name
      {get("/api/render?%ed%a0%80"), "%ED%A0%80", ""},  // a surrogate
      {get("/api/fit?%c0%80"), "%C0%80", ""},
      {get("/api/fit?sex=female&style=pencil&stature=%f4%90%80%80"), "stature", "%F4%90%80%80"},  // past U+10FFFF
      {post("/api/render?skin=%fe", ""), "skin", "%FE"},
      {post("/api/render", "outfit=%ff%ff&size=160x200"), "outfit", "%FF%FF"},
  };
  for (const Case& c : cases) {
    const HttpAnswer answer = ask(c.request);
    EXPECT_EQ(answer.status, 400) << c.request;
    const nlohmann::json body = json(answer);
    EXPECT_EQ(body.value("parameter", ""), c.parameter) << c.request;
    EXPECT_EQ(body.value("value", ""), c.value) << c.request;
    // Refused as text that is not UTF-8, not for what the bytes fail to be after (a number, a
    // garment).
    EXPECT_EQ(body.value("error", ""), c.parameter[0] == '%' ? "a parameter name that is not UTF-8" : "not UTF-8")
        << c.request;
    EXPECT_FALSE(body.value("accepted", "").empty()) << c.request;
  }
}

TEST_F(HttpServiceExchange, AnEchoedValueIsCutBeforeAWholeCharacter) {
  // 63 bytes of 'a' and a two-byte é: cut to 64 bytes, the é would be half a character.
  const HttpAnswer answer = ask(get("/api/render?pose=" + std::string(63, 'a') + "%C3%A9"));
  EXPECT_EQ(answer.status, 400);
  EXPECT_EQ(json(answer).value("value", ""), std::string(63, 'a'));
  const HttpAnswer style = ask(get("/api/render?outfit=" + std::string(31, 'b') + "%C3%A9:M"));
  EXPECT_EQ(style.status, 400);
  EXPECT_EQ(json(style).value("error", ""), "no style named " + std::string(31, 'b'));
}

TEST_F(HttpServiceExchange, AJobIdThatIsNotUtf8IsNoSuchJob) {
  HttpAnswer answer = ask(get("/api/jobs/%ff%fe"));
  EXPECT_EQ(answer.status, 404);
  EXPECT_EQ(json(answer).value("id", ""), "%FF%FE");
  std::string many;
  for (int i = 0; i < 40; ++i) many += "%ff";
  answer = ask(get("/api/jobs/" + many));
  EXPECT_EQ(answer.status, 404);
  EXPECT_EQ(json(answer).value("id", ""), upper(many.substr(0, 63)));  // 21 whole escapes
}

TEST_F(HttpServiceExchange, AMethodAKnownPathDoesNotTakeIs405WithAllow) {
  std::map<std::string, std::set<std::string>> taken;
  for (const HttpService::Route& route : HttpService::routes()) taken[route.path].insert(route.method);
  ASSERT_GE(taken.size(), 9u);
  for (const auto& [path, methods] : taken) {
    const std::string target = path == "/api/jobs/{id}" ? "/api/jobs/0123" : path;
    const std::string allow = methods.count("POST") ? "GET, HEAD, POST" : "GET, HEAD";
    for (const std::string method : {"PUT", "PATCH", "DELETE", "OPTIONS", "TRACE", "POST"}) {
      if (methods.count(method)) continue;
      const HttpAnswer answer = ask(method + " " + target + " HTTP/1.1\r\nHost: t\r\nContent-Length: 0\r\n\r\n");
      EXPECT_EQ(answer.status, 405) << method << " " << target;
      EXPECT_EQ(answer.header("Allow"), allow) << method << " " << target;
      EXPECT_TRUE(json(answer).contains("error")) << method << " " << target;
    }
  }
}

TEST_F(HttpServiceExchange, ARefusedRequestsBodyIsReadNotTakenForTheNextRequest) {
  const std::string hidden = get("/api/catalogue");
  const std::vector<std::string> answers =
      service_->exchange("PUT /api/render HTTP/1.1\r\nHost: t\r\nContent-Length: " + std::to_string(hidden.size()) +
                         "\r\n\r\n" + hidden + get("/healthz"));
  ASSERT_EQ(answers.size(), 2u);
  HttpAnswer first, second;
  EXPECT_EQ(figment::test::readAnswer(answers[0], first), "");
  EXPECT_EQ(figment::test::readAnswer(answers[1], second), "");
  EXPECT_EQ(first.status, 405);
  EXPECT_EQ(second.status, 200);
  EXPECT_TRUE(json(second).contains("workers"));  // /healthz's, not the catalogue's
}

TEST_F(HttpServiceExchange, ARequestWhoseBodyHasNoClearEndIsRefusedAndItsConnectionClosed) {
  const std::string hidden = get("/api/catalogue");
  const std::string length = "Content-Length: " + std::to_string(hidden.size()) + "\r\n";
  // cpp-httplib reads no body for GET, HEAD, OPTIONS, TRACE (400); a chunked body or one
  // without a length it reads with no bound (411); a method the path does not take is 405.
  for (const auto& [head, status] : std::vector<std::pair<std::string, int>>{
           {"GET /healthz HTTP/1.1\r\n" + length, 400},
           {"HEAD /healthz HTTP/1.1\r\n" + length, 400},
           {"OPTIONS /healthz HTTP/1.1\r\n" + length, 405},  // a refused method stays 405
           {"TRACE /nope HTTP/1.1\r\n" + length, 400},
           {"GET /healthz HTTP/1.1\r\nTransfer-Encoding: chunked\r\n", 400},
           {"POST /api/render HTTP/1.1\r\nContent-Length: 1e3\r\n", 400},  // strtoull: 1, the rest a request
           {"POST /api/render HTTP/1.1\r\n" + length + "Content-Length: 0\r\n", 400},
           {"POST /api/render HTTP/1.1\r\n" + length + "Transfer-Encoding: chunked\r\n", 411},
           {"POST /api/render HTTP/1.1\r\nTransfer-Encoding: gzip, chunked\r\n", 411},
           {"POST /api/render HTTP/1.1\r\n", 411},  // no length: httplib reads to the connection's end
           {"PUT /api/catalogue HTTP/1.1\r\n", 405},
           {"GET /nope HTTP/1.1\r\n" + length, 400},
       }) {
    const std::vector<std::string> answers = service_->exchange(head + "Host: t\r\n\r\n" + hidden);
    ASSERT_FALSE(answers.empty()) << head;
    HttpAnswer answer;
    EXPECT_EQ(figment::test::readAnswer(answers[0], answer), "") << head;
    EXPECT_EQ(answer.status, status) << head;
    EXPECT_EQ(answer.header("Connection"), "close") << head;
    EXPECT_EQ(answer.count("Connection"), 1u) << head;
    EXPECT_EQ(answer.count("Keep-Alive"), 0u) << head;
    if (head[0] != 'H') {
      EXPECT_TRUE(json(answer).contains("error")) << head;
    }
  }
  // Controls: an empty body declared where none is read, a body of its length where one is.
  EXPECT_EQ(ask("GET /healthz HTTP/1.1\r\nContent-Length: 0\r\n\r\n").status, 200);
  const HttpAnswer form = ask(post("/api/render", "size=160x200"));
  EXPECT_EQ(form.status, 503);  // judged valid, refused by a pool of no workers
  EXPECT_EQ(form.count("Connection"), 0u);
}

TEST_F(HttpServiceExchange, ARequestHttplibCannotReadWholeClosesItsConnection) {
  const std::string next = get("/api/catalogue");
  for (const std::string& request : std::vector<std::string>{
           "POST /api/render HTTP/1.1\r\nContent-Length: 9000\r\n\r\n" + next,    // past the payload limit: 413
           "GET /healthz?" + std::string(9000, 'a') + " HTTP/1.1\r\n\r\n",        // past the URL limit: 414
           "GET /healthz HTTP/1.1\r\nX: " + std::string(9000, 'a') + "\r\n\r\n",  // a header line past it: 400
           "GET /healthz HTTP/1.2\r\n\r\n",                                       // no such version: 400
       }) {
    const std::vector<std::string> answers = service_->exchange(request + next);
    ASSERT_FALSE(answers.empty());
    HttpAnswer answer;
    EXPECT_EQ(figment::test::readAnswer(answers[0], answer), "");
    EXPECT_GE(answer.status, 400) << request.substr(0, 40);
    EXPECT_EQ(answer.header("Connection"), "close") << request.substr(0, 40);
    EXPECT_TRUE(json(answer).contains("error")) << request.substr(0, 40);
  }
}

TEST_F(HttpServiceExchange, AnUnknownPathIs404WhateverTheMethod) {
  for (const std::string path : {"/nope", "/api", "/api/render/x", "/api/jobs/", "/api/jobs/a/b", "/healthz/"})
    for (const std::string method : {"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS", "TRACE"}) {
      const HttpAnswer answer = ask(method + " " + path + " HTTP/1.1\r\nHost: t\r\nContent-Length: 0\r\n\r\n");
      EXPECT_EQ(answer.status, 404) << method << " " << path;
      if (method != "HEAD") {
        EXPECT_TRUE(json(answer).contains("error")) << method << " " << path;
      }
    }
}

TEST_F(HttpServiceExchange, EveryRouteIsServedAndARenderWithoutWorkersIs503) {
  for (const HttpService::Route& route : HttpService::routes()) {
    const std::string target = route.path == "/api/jobs/{id}" ? "/api/jobs/0123" : route.path;
    const HttpAnswer answer = ask(route.method == "GET" ? get(target) : post(target, "size=160x200"));
    EXPECT_NE(answer.status, 405) << route.method << " " << target;
    if (answer.header("Content-Type") == "application/json" && answer.status == 404) {
      EXPECT_EQ(json(answer).value("error", ""), "no such job");  // the route's own 404, not the path's
    } else {
      EXPECT_NE(answer.status, 404) << route.method << " " << target;
    }
  }
  for (const std::string& request : {get("/api/render?size=160x200"), post("/api/render", "size=160x200")}) {
    const HttpAnswer answer = ask(request);
    EXPECT_EQ(answer.status, 503) << request;
    EXPECT_FALSE(answer.header("Retry-After").empty()) << request;
    EXPECT_TRUE(json(answer).contains("error"));
  }
}

TEST_F(HttpServiceExchange, TheDocumentListsTheStatusEachOperationAnswersHere) {
  const nlohmann::json document = nlohmann::json::parse(findWebAsset("/openapi.json")->content);
  struct Case {
    std::string path, method, request;
  };
  const Case cases[] = {
      {"/api/render", "get", get("/api/render?stature=%ff")},
      {"/api/render", "get", get("/api/render?size=160x200")},  // 503: no workers
      {"/api/render", "post", post("/api/render", "skin=%fe")},
      {"/api/render", "post", post("/api/render", "size=160x200")},
      {"/api/render", "post", "POST /api/render HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n"},  // 411
      {"/api/fit", "get", get("/api/fit?%c0%80")},
      {"/api/fit", "get", get("/api/fit?sex=female&style=pencil&stature=1.68&bust=0.88&waist=0.72&hips=0.96")},
      {"/api/jobs/{id}", "get", get("/api/jobs/%ff")},
  };
  for (const Case& c : cases) {
    const int status = ask(c.request).status;
    EXPECT_TRUE(document["paths"][c.path][c.method]["responses"].contains(std::to_string(status)))
        << c.method << " " << c.path << ": " << status;
  }
}
