#pragma once
// One render worker: this same program started again in its worker mode (fork + exec, so
// the worker has Coin, OSMesa and its drape context to itself), talking over a Unix
// socket pair. The server side holds it; a worker that dies or hangs is killed and
// started again by its owner.

#include <sys/types.h>

#include <string>
#include <vector>

#include "serve/workers/FrameChannel.h"

namespace figment::serve {

class WorkerProcess {
 public:
  // `program` and its arguments; the worker's end of the socket is given to it as fd 3.
  WorkerProcess(std::string program, std::vector<std::string> arguments);
  ~WorkerProcess();
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  // Starts the worker; "" or why not.
  std::string start();
  bool running() const { return pid_ > 0; }
  pid_t pid() const { return pid_; }
  const FrameChannel& channel() const { return channel_; }
  // SIGKILL, then waits for it: nothing of it is left.
  void stop();

  static constexpr int kWorkerFd = 3;

 private:
  // The worker's environment: the server's, with OMP_NUM_THREADS=1 unless it is set.
  std::vector<char*> environment();

  std::string program_;
  std::string oneThread_ = "OMP_NUM_THREADS=1";
  std::vector<std::string> arguments_;
  pid_t pid_ = -1;
  FrameChannel channel_;
};

}  // namespace figment::serve
