#include "serve/http/ExchangeServer.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace figment::serve {

namespace {

// A connection held in memory: reads what the client sent, keeps what the server writes.
class MemoryStream : public httplib::Stream {
 public:
  MemoryStream(std::string_view input, std::string remoteAddress)
      : input_(input), remoteAddress_(std::move(remoteAddress)) {}

  bool is_readable() const override { return position_ < input_.size(); }
  bool is_writable() const override { return true; }
  ssize_t read(char* ptr, size_t size) override {
    const size_t n = std::min(size, input_.size() - position_);  // 0: the client sent nothing more
    std::memcpy(ptr, input_.data() + position_, n);
    position_ += n;
    return static_cast<ssize_t>(n);
  }
  ssize_t write(const char* ptr, size_t size) override {
    output_.append(ptr, size);
    return static_cast<ssize_t>(size);
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override { ip = remoteAddress_, port = 0; }
  void get_local_ip_and_port(std::string& ip, int& port) const override { ip = "127.0.0.1", port = 0; }
  // No socket: below any select() bound cpp-httplib checks, never a descriptor it could use.
  socket_t socket() const override { return INVALID_SOCKET; }

  bool drained() const { return position_ >= input_.size(); }
  std::string takeOutput() { return std::exchange(output_, std::string()); }

 private:
  std::string_view input_;
  size_t position_ = 0;
  std::string remoteAddress_;
  std::string output_;
};

}  // namespace

std::vector<std::string> ExchangeServer::exchange(std::string_view bytes, const std::string& remoteAddress) {
  MemoryStream stream(bytes, remoteAddress);
  std::vector<std::string> answers;
  // As cpp-httplib's connection loop: at most its keep-alive count of requests, the last one
  // answered "Connection: close"; a request it cannot go on from (or one asking to close)
  // ends the connection.
  for (size_t count = keep_alive_max_count_; count > 0 && !stream.drained(); --count) {
    bool closed = false;
    const bool goOn = process_request(stream, count == 1, closed, nullptr);
    if (std::string answer = stream.takeOutput(); !answer.empty()) answers.push_back(std::move(answer));
    if (!goOn || closed) break;
  }
  return answers;
}

}  // namespace figment::serve
