#include "serve/workers/FrameChannel.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

namespace figment::serve {

bool FrameChannel::send(const std::string& bytes) const {
  if (bytes.size() > kMaxFrame) return false;
  const std::uint32_t n = std::uint32_t(bytes.size());
  const unsigned char header[4] = {static_cast<unsigned char>(n), static_cast<unsigned char>(n >> 8),
                                   static_cast<unsigned char>(n >> 16), static_cast<unsigned char>(n >> 24)};
  std::string frame(reinterpret_cast<const char*>(header), 4);
  frame += bytes;
  size_t sent = 0;
  while (sent < frame.size()) {
    // MSG_NOSIGNAL: a worker that died is an error here, not a SIGPIPE for the server.
    const ssize_t k = ::send(fd_, frame.data() + sent, frame.size() - sent, MSG_NOSIGNAL);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    sent += size_t(k);
  }
  return true;
}

FrameChannel::Result FrameChannel::readFully(char* data, size_t size, Clock::time_point deadline) const {
  size_t got = 0;
  while (got < size) {
    int waitMs = -1;
    if (deadline != Clock::time_point::max()) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return Result::kTimedOut;
      waitMs = int(std::min<long long>(left, 1 << 30));
    }
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, waitMs);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return Result::kClosed;
    if (ready == 0) return Result::kTimedOut;
    const ssize_t k = ::read(fd_, data + got, size - got);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return Result::kClosed;
    got += size_t(k);
  }
  return Result::kOk;
}

FrameChannel::Result FrameChannel::receive(std::string& bytes, Clock::time_point deadline) const {
  unsigned char header[4];
  if (Result r = readFully(reinterpret_cast<char*>(header), 4, deadline); r != Result::kOk) return r;
  const std::uint32_t n = std::uint32_t(header[0]) | std::uint32_t(header[1]) << 8 | std::uint32_t(header[2]) << 16 |
                          std::uint32_t(header[3]) << 24;
  if (n > kMaxFrame) return Result::kClosed;  // not our peer's frame: treat the peer as gone
  bytes.assign(n, '\0');
  return readFully(bytes.data(), n, deadline);
}

}  // namespace figment::serve
