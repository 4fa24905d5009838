#pragma once
// cpp-httplib's server, which can also answer requests held in memory: the bytes a client
// sends on one connection in, the bytes it would read back out, through the very code that
// answers a socket (httplib::Server::process_request: the request line and header limits,
// the routing, the error handlers, the response writer). So a test or a fuzz target drives
// the whole exchange in process, with no socket and no thread, and sees what a client sees.
// Included only inside figment_serve, which compiles with cpp-httplib's pkg-config flags (its
// classes' layout depends on them); HttpService::exchange is the way in from outside.

#include <httplib.h>

#include <string>
#include <string_view>
#include <vector>

namespace figment::serve {

class ExchangeServer : public httplib::Server {
 public:
  // Answers the requests in `bytes` one after another as on one keep-alive connection from
  // `remoteAddress` that sends them and then nothing more: one answer's bytes each (its
  // status line, headers and body, a "100 Continue" before it where asked), until the
  // bytes are used up or the connection would close.
  std::vector<std::string> exchange(std::string_view bytes, const std::string& remoteAddress);
};

}  // namespace figment::serve
