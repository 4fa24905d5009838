#pragma once
// Messages between the server and a worker process over one Unix socket: each a 4-byte
// length (little end first) and that many bytes. Reading waits until a deadline, so a
// worker that hangs is found out and one that dies is seen as the socket closing.

#include <chrono>
#include <cstdint>
#include <string>

namespace figment::serve {

class FrameChannel {
 public:
  enum class Result { kOk, kClosed, kTimedOut };
  using Clock = std::chrono::steady_clock;
  static constexpr std::uint32_t kMaxFrame = 64u << 20;  // bytes: a 1600x1200 PNG is far less

  explicit FrameChannel(int fd = -1) : fd_(fd) {}
  int fd() const { return fd_; }

  // Writes the whole frame; false when the other end is gone.
  bool send(const std::string& bytes) const;
  // Reads one frame into `bytes`, waiting no later than `deadline` (never: Clock::time_point::max()).
  Result receive(std::string& bytes, Clock::time_point deadline) const;

 private:
  Result readFully(char* data, size_t size, Clock::time_point deadline) const;
  int fd_;
};

}  // namespace figment::serve
