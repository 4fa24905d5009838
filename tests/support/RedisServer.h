#pragma once
// A redis-server of a test's own on a Unix socket in a temporary folder, nothing saved,
// started by the constructor and killed (and waited for) by the destructor. Ready once it
// answers: the constructor polls for that, with no clock of its own (ctest's TIMEOUT bounds
// a Redis that never comes).

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <thread>
#include <vector>

#include "serve/workers/RedisConnection.h"
#include "support/TempDir.h"

namespace figment::test {

class RedisServer {
 public:
  explicit RedisServer(const std::string& program) : socket_((dir_.path() / "redis.sock").string()) {
    std::vector<std::string> arguments = {program,        "--port", "0",     "--unixsocket",      socket_, "--save", "",
                                          "--appendonly", "no",     "--dir", dir_.path().string()};
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    argv.push_back(nullptr);
    pid_ = ::fork();
    if (pid_ == 0) {
      const int quiet = ::open("/dev/null", O_WRONLY);  // its start-up banner is not the test's
      ::dup2(quiet, STDOUT_FILENO);
      ::execv(program.c_str(), argv.data());
      ::_exit(127);
    }
    serve::RedisConnection::Options options;
    options.retryInterval = 0;  // s: try again on every check
    serve::RedisConnection probe(socket_, options);
    while (pid_ > 0 && !probe.check() && ::waitpid(pid_, nullptr, WNOHANG) == 0) std::this_thread::yield();
  }
  ~RedisServer() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  RedisServer(const RedisServer&) = delete;
  RedisServer& operator=(const RedisServer&) = delete;

  // Its URL for RedisConnection: the socket's path.
  const std::string& url() const { return socket_; }

 private:
  TempDir dir_;
  std::string socket_;
  pid_t pid_ = -1;
};

}  // namespace figment::test
