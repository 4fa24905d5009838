// The work queue on a Redis of the test's own (tests/support/RedisServer.h): a job is added
// once however often it is asked for, delivered to one consumer, recorded done or failed
// when acknowledged, taken over by another consumer when left pending, and counted in the
// progress figment-precompute reports.

#include <gtest/gtest.h>

#include <filesystem>
#include <thread>

#include "serve/workers/JobQueue.h"
#include "support/RedisServer.h"

using namespace figment::serve;

namespace {

class JobQueueTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(FIGMENT_REDIS_SERVER)) GTEST_SKIP() << "no redis-server";
    server_ = std::make_unique<figment::test::RedisServer>(FIGMENT_REDIS_SERVER);
    redis_ = std::make_unique<RedisConnection>(server_->url(), RedisConnection::Options{});
    queue_ = std::make_unique<JobQueue>(*redis_);
    ASSERT_EQ(queue_->prepare(), "");
  }

  JobProgress progress() {
    std::string error;
    const std::optional<JobProgress> now = queue_->progress(error);
    EXPECT_TRUE(now) << error;
    return now.value_or(JobProgress{});
  }

  std::unique_ptr<figment::test::RedisServer> server_;
  std::unique_ptr<RedisConnection> redis_;
  std::unique_ptr<JobQueue> queue_;
};

constexpr double kNow = 0.001;  // s: claimAfter and wait, as short as Redis takes them

}  // namespace

TEST_F(JobQueueTest, AJobIsAddedOnceAndKeyedByItsRequest) {
  std::string error;
  EXPECT_EQ(queue_->add({"a=1", "b=2", "a=1"}, error), 2) << error;
  EXPECT_EQ(queue_->add({"a=1"}, error), 0) << error;  // queued already
  const JobProgress now = progress();
  EXPECT_EQ(now.added, 2);
  EXPECT_EQ(now.queued, 2);
  const std::optional<Job> job = queue_->next("w/0", 600, kNow);
  ASSERT_TRUE(job);
  EXPECT_EQ(job->request, "a=1");
  EXPECT_EQ(job->key, JobQueue::keyOf("a=1"));
  EXPECT_EQ(job->deliveries, 1);
}

TEST_F(JobQueueTest, ACompletedJobIsDoneAndNotDeliveredAgain) {
  std::string error;
  ASSERT_EQ(queue_->add({"a=1"}, error), 1) << error;
  const std::optional<Job> job = queue_->next("w/0", 600, kNow);
  ASSERT_TRUE(job);
  EXPECT_EQ(progress().pending, 1);
  ASSERT_TRUE(queue_->complete(*job, "tag", true));
  const JobProgress now = progress();
  EXPECT_EQ(now.done, 1);
  EXPECT_EQ(now.queued, 0);
  EXPECT_EQ(now.pending, 0);
  EXPECT_FALSE(queue_->next("w/1", kNow, kNow));  // nothing left, not even to take over
  EXPECT_EQ(queue_->add({"a=1"}, error), 0);      // done: not added again
}

TEST_F(JobQueueTest, AFailedJobIsRecordedWithItsErrorAndMayBeAddedAgain) {
  std::string error;
  ASSERT_EQ(queue_->add({"a=1"}, error), 1) << error;
  const std::optional<Job> job = queue_->next("w/0", 600, kNow);
  ASSERT_TRUE(job);
  ASSERT_TRUE(queue_->fail(*job, "400: bad"));
  JobProgress now = progress();
  EXPECT_EQ(now.failed, 1);
  ASSERT_EQ(now.failures.size(), 1u);
  EXPECT_EQ(now.failures[0], (std::pair<std::string, std::string>("a=1", "400: bad")));
  EXPECT_EQ(queue_->add({"a=1"}, error), 1);  // tried again
  now = progress();
  EXPECT_EQ(now.failed, 0);
  EXPECT_EQ(now.queued, 1);
}

TEST_F(JobQueueTest, AJobLeftPendingIsTakenOverByAnotherConsumer) {
  std::string error;
  ASSERT_EQ(queue_->add({"a=1"}, error), 1) << error;
  const std::optional<Job> first = queue_->next("w/0", 600, kNow);  // and never acknowledged
  ASSERT_TRUE(first);
  std::optional<Job> again;
  // Taken over once it has been idle claimAfter (1 ms): polled, as a job worker does.
  while (!(again = queue_->next("w/1", kNow, kNow))) std::this_thread::yield();
  EXPECT_EQ(again->id, first->id);
  EXPECT_EQ(again->request, "a=1");
  EXPECT_EQ(again->deliveries, 2);
  const JobProgress now = progress();
  ASSERT_EQ(now.consumers.size(), 1u);  // only its new consumer holds it
  EXPECT_EQ(now.consumers[0].first, "w/1");
}

TEST_F(JobQueueTest, AJobMadeTwiceIsCounted) {
  std::string error;
  ASSERT_EQ(queue_->add({"a=1"}, error), 1) << error;
  const std::optional<Job> first = queue_->next("w/0", 600, kNow);
  ASSERT_TRUE(first);
  std::optional<Job> again;
  while (!(again = queue_->next("w/1", kNow, kNow))) std::this_thread::yield();
  ASSERT_TRUE(queue_->complete(*again, "tag", true));
  ASSERT_TRUE(queue_->complete(*first, "tag", true));  // the first worker finished after all
  EXPECT_EQ(progress().madeTwice, 1);
}
