// The OpenAPI document kept beside the code lists every route the service answers, and
// nothing else; every route but the API's own is an embedded file.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "serve/HttpService.h"
#include "serve/WebAssets.h"

using namespace figment::serve;

TEST(HttpService, TheOpenApiDocumentListsEveryRoute) {
  const WebAsset* document = findWebAsset("/openapi.json");
  ASSERT_NE(document, nullptr);
  const nlohmann::json json = nlohmann::json::parse(document->content);
  EXPECT_EQ(json["openapi"].get<std::string>().substr(0, 2), "3.");
  std::set<std::string> listed;
  for (const auto& [path, item] : json["paths"].items()) {
    listed.insert(path);
    EXPECT_TRUE(item.contains("get")) << path;
  }
  const std::set<std::string> routes(HttpService::routes().begin(), HttpService::routes().end());
  EXPECT_EQ(listed, routes);
}

TEST(HttpService, EveryEmbeddedFileIsARoute) {
  const std::set<std::string> routes(HttpService::routes().begin(), HttpService::routes().end());
  ASSERT_FALSE(webAssets().empty());
  for (const WebAsset& asset : webAssets()) {
    EXPECT_TRUE(routes.count(std::string(asset.path))) << asset.path;
    EXPECT_FALSE(asset.content.empty()) << asset.path;
  }
  EXPECT_EQ(findWebAsset("/../openapi.json"), nullptr);  // exact paths only
}
