#include "serve/workers/WorkerProcess.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

extern char** environ;

namespace figment::serve {

WorkerProcess::WorkerProcess(std::string program, std::vector<std::string> arguments)
    : program_(std::move(program)), arguments_(std::move(arguments)) {}

WorkerProcess::~WorkerProcess() {
  stop();
}

std::vector<char*> WorkerProcess::environment() {
  // One OpenMP thread per worker unless told otherwise: the service runs a worker per
  // core, and OpenMP teams in every worker oversubscribe the cores (a T-shirt's implicit
  // drape took 15x longer with two threads on two busy cores than with one).
  std::vector<char*> envp;
  bool threadsSet = false;
  for (char** entry = environ; *entry; ++entry) {
    threadsSet = threadsSet || std::strncmp(*entry, "OMP_NUM_THREADS=", 16) == 0;
    envp.push_back(*entry);
  }
  if (!threadsSet) envp.push_back(oneThread_.data());
  envp.push_back(nullptr);
  return envp;
}

std::string WorkerProcess::start() {
  stop();
  int fds[2];
  // Close-on-exec: no worker inherits another's socket (or the server's listening one,
  // closed in the child below).
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
    return std::string("cannot make a socket pair: ") + std::strerror(errno);
  std::vector<char*> argv;
  argv.push_back(program_.data());
  for (std::string& argument : arguments_) argv.push_back(argument.data());
  argv.push_back(nullptr);
  std::vector<char*> envp = environment();
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return std::string("cannot start a worker: ") + std::strerror(errno);
  }
  if (pid == 0) {
    // The child: only async-signal-safe calls until exec.
    if (fds[1] == kWorkerFd ? ::fcntl(kWorkerFd, F_SETFD, 0) < 0 : ::dup2(fds[1], kWorkerFd) < 0) ::_exit(127);
    ::close_range(kWorkerFd + 1, ~0u, 0);
    // The server's blocked stop signals and ignored SIGPIPE would outlive exec.
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::signal(SIGPIPE, SIG_DFL);
    // A server or job worker killed outright (SIGKILL) takes its workers with it, rather
    // than leaving them to finish a render nobody reads. (The parent is the pool's thread
    // that started it, which lives as long as the pool.)
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // it died already
    ::execve(program_.c_str(), argv.data(), envp.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  pid_ = pid;
  channel_ = FrameChannel(fds[0]);
  return "";
}

void WorkerProcess::stop() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  if (channel_.fd() >= 0) ::close(channel_.fd());
  pid_ = -1;
  channel_ = FrameChannel();
}

}  // namespace figment::serve
