// The worker pool with stand-in workers (tests/support/fake_serve_worker.py, which speaks
// the pool's frames): a request's kind reaches the worker beside its text, identical
// requests in flight are made once, a full queue refuses at once, a worker that dies or
// runs past its time limit fails only its own request and is started again. Waits are on
// what the pool reports (its load), never on a clock.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <future>
#include <thread>

#include "serve/workers/WorkerPool.h"
#include "support/TempDir.h"

using namespace figment::serve;

namespace {

PoolOptions fakeWorkers(int workers, int queue, double timeLimit = 600) {
  PoolOptions options;
  options.program = FIGMENT_PYTHON;
  options.arguments = {FIGMENT_SOURCE_DIR "/tests/support/fake_serve_worker.py"};
  options.workers = workers;
  options.queue = queue;
  options.timeLimit = timeLimit;  // s: past it a worker is killed (504)
  return options;
}

// Polls `done` until it holds: the pool's state changes on other threads.
template <class Condition>
void waitUntil(Condition done) {
  while (!done()) std::this_thread::yield();
}

// A FIFO "wait:" requests block on until release(): it holds the FIFO open for writing, so
// the worker's open never blocks, and each release writes one token, letting one waiting
// request through (the stand-in reads exactly one).
class Gate {
 public:
  Gate(const figment::test::TempDir& dir, const std::string& name) : path_((dir.path() / name).string()) {
    ::mkfifo(path_.c_str(), 0600);
    fd_ = ::open(path_.c_str(), O_RDWR);  // read and write: opening blocks on no other end
  }
  ~Gate() { ::close(fd_); }
  Gate(const Gate&) = delete;
  Gate& operator=(const Gate&) = delete;
  std::string request() const { return "wait:" + path_; }
  // Lets `count` waiting requests through (tokens beyond those waiting are never read).
  void release(int count = 1) const {
    for (int i = 0; i < count; ++i) EXPECT_EQ(::write(fd_, "go\n", 3), 3);
  }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace

TEST(WorkerPool, TheKindReachesTheWorkerBesideTheText) {
  WorkerPool pool(fakeWorkers(1, 4));
  const auto fit = pool.ask({JobKind::kFit, "echo:sex=female"});
  ASSERT_NE(fit, nullptr);
  EXPECT_EQ(fit->status, 200);
  EXPECT_EQ(fit->body, "fit:sex=female");
  const auto render = pool.ask({JobKind::kRender, "echo:sex=female"});
  ASSERT_NE(render, nullptr);
  EXPECT_EQ(render->body, "render:sex=female");  // the same text of another kind: other work
}

TEST(WorkerPool, IdenticalRequestsInFlightAreMadeOnce) {
  const figment::test::TempDir dir;
  const Gate gate(dir, "gate");
  WorkerPool pool(fakeWorkers(1, 4));
  const WorkRequest held{JobKind::kRender, gate.request()};
  auto first = std::async(std::launch::async, [&] { return pool.ask(held); });
  auto second = std::async(std::launch::async, [&] { return pool.ask(held); });
  // Both wait, and the worker has taken a job (and holds it at the gate).
  waitUntil([&] {
    const WorkerPool::Load load = pool.load();
    return load.waiting == 2 && load.busy == 1;
  });
  EXPECT_EQ(pool.load().queued, 0);  // the second joined the first's job: none waits behind it
  gate.release(2);                   // enough for two jobs, should the pool (wrongly) have made two
  const auto a = first.get(), b = second.get();
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a, b);  // one answer, shared
  // The worker was asked once: this is its second request.
  EXPECT_EQ(pool.ask({JobKind::kRender, "count"})->body, "2");
}

TEST(WorkerPool, AFullQueueRefusesAtOnce) {
  const figment::test::TempDir dir;
  const Gate gate(dir, "gate");
  WorkerPool pool(fakeWorkers(1, 1));
  auto held = std::async(std::launch::async, [&] { return pool.ask({JobKind::kRender, gate.request()}); });
  waitUntil([&] { return pool.load().busy == 1; });
  auto queued = std::async(std::launch::async, [&] { return pool.ask({JobKind::kFit, "echo:queued"}); });
  waitUntil([&] { return pool.load().queued == 1; });
  // Refused at once: the ask returns without the worker; were it queued instead, the queue
  // would show it and the gate is opened for all so the test ends.
  auto refused = std::async(std::launch::async, [&] { return pool.ask({JobKind::kRender, "echo:one too many"}); });
  waitUntil([&] {
    return refused.wait_for(std::chrono::seconds(0)) == std::future_status::ready || pool.load().queued == 2;
  });
  gate.release();
  EXPECT_EQ(refused.get(), nullptr);
  EXPECT_EQ(held.get()->body, "released");
  EXPECT_EQ(queued.get()->body, "fit:queued");
}

TEST(WorkerPool, AWorkerThatDiesFailsItsRequestAndIsReplaced) {
  WorkerPool pool(fakeWorkers(1, 4));
  const auto died = pool.ask({JobKind::kRender, "die"});
  ASSERT_NE(died, nullptr);
  EXPECT_EQ(died->status, 502);
  EXPECT_EQ(pool.load().restarts, 1);
  const auto next = pool.ask({JobKind::kRender, "count"});
  EXPECT_EQ(next->status, 200);
  EXPECT_EQ(next->body, "1");  // a new process: its first request
}

TEST(WorkerPool, AWorkerPastItsTimeLimitIsKilledAndReplaced) {
  WorkerPool pool(fakeWorkers(1, 4, 0.5));
  const auto hung = pool.ask({JobKind::kRender, "hang"});
  ASSERT_NE(hung, nullptr);
  EXPECT_EQ(hung->status, 504);
  EXPECT_EQ(pool.load().restarts, 1);  // replaced (a replacement's first answer: the test above)
}

TEST(WorkerPool, AWorkersRefusalIsItsAnswerNotAFailure) {
  WorkerPool pool(fakeWorkers(1, 4));
  const auto refused = pool.ask({JobKind::kFit, "refuse"});
  ASSERT_NE(refused, nullptr);
  EXPECT_EQ(refused->status, 400);
  EXPECT_EQ(refused->body, R"({"error": "refused"})");
  EXPECT_EQ(pool.load().restarts, 0);
}

TEST(WorkerPool, APoolWithoutWorkersTakesNothing) {
  WorkerPool pool(fakeWorkers(0, 4));
  EXPECT_EQ(pool.ask({JobKind::kRender, "echo:x"}), nullptr);
  EXPECT_EQ(pool.load().workers, 0);
}

// The workers a figment-serve of these options starts: itself again in worker mode, with its
// scenes, drape cache, advice threads and Redis; four requests waiting per worker unless told.
TEST(WorkerPool, WorkerPoolOptionsStartTheProgramInWorkerMode) {
  ServeOptions options;
  options.workers = 3;
  options.scenesFolder = "/s";
  options.cacheFolder = "/c";
  PoolOptions pool = workerPoolOptions(options, "/bin/figment-serve");
  EXPECT_EQ(pool.program, "/bin/figment-serve");
  EXPECT_EQ(pool.arguments, (std::vector<std::string>{"--worker", "--scenes", "/s", "--cache", "/c"}));
  EXPECT_EQ(pool.queue, 12);
  options.redisUrl = "redis://h";
  options.queue = 2;
  pool = workerPoolOptions(options, "/bin/figment-serve");
  EXPECT_EQ(pool.arguments.back(), std::to_string(options.redisTtl));
  EXPECT_EQ(pool.queue, 2);
  // An advice's threads go to the workers only when given (their own default: one per core).
  options.adviceThreads = 1;
  pool = workerPoolOptions(options, "/bin/figment-serve");
  EXPECT_EQ(std::vector<std::string>(pool.arguments.begin() + 5, pool.arguments.begin() + 7),
            (std::vector<std::string>{"--advice-threads", "1"}));
}
