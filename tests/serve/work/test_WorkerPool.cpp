// The worker pool with stand-in workers (tests/support/fake_serve_worker.py, which speaks
// the pool's frames): a request's kind reaches the worker beside its text, identical
// requests in flight are made once, a full queue refuses at once, a worker that dies or
// runs past its time limit fails only its own request and is started again. Waits are on
// what the pool reports (its load), never on a clock.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <future>
#include <thread>

#include "serve/work/WorkerPool.h"
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

// A FIFO a "wait:" request blocks on until release() writes its line.
class Gate {
 public:
  explicit Gate(const figment::test::TempDir& dir, const std::string& name) : path_((dir.path() / name).string()) {
    ::mkfifo(path_.c_str(), 0600);
  }
  std::string request() const { return "wait:" + path_; }
  void release() const { std::ofstream(path_) << "go\n"; }

 private:
  std::string path_;
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
  waitUntil([&] { return pool.load().waiting == 2; });  // both wait on the one job
  EXPECT_EQ(pool.load().busy, 1);
  EXPECT_EQ(pool.load().queued, 0);
  gate.release();
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
  EXPECT_EQ(pool.ask({JobKind::kRender, "echo:one too many"}), nullptr);
  gate.release();
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
  EXPECT_EQ(pool.load().restarts, 1);
  EXPECT_EQ(pool.ask({JobKind::kRender, "echo:after"})->body, "render:after");
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
// scenes, drape cache and Redis; four requests waiting per worker unless told.
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
}
