#pragma once
// The files the server sends as they are, embedded in the program at build time
// (serve/http/EmbedFiles.cmake): the shopper's page and the OpenAPI document. Looked up by
// exact path only: no file is read at run time, so no request path reaches the disk.

#include <string_view>
#include <vector>

namespace figment::serve {

struct WebAsset {
  std::string_view path;  // "/", "/app.js", ...
  std::string_view type;  // its Content-Type
  std::string_view content;
};

// Every embedded file (the page's and /openapi.json).
const std::vector<WebAsset>& webAssets();
// The one at `path`, or null.
const WebAsset* findWebAsset(std::string_view path);

}  // namespace figment::serve
