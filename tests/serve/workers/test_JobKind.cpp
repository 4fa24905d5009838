// A job's kind: its frame name reads back, an unknown name is no kind, and what an answer's
// ETag digests is a render's canonical text as it is and a fit's after "fit?" (so the tags
// are those of when the kind was that prefix, and a fit's never equals a render's).

#include <gtest/gtest.h>

#include "serve/workers/JobKind.h"

using namespace figment::serve;

TEST(JobKind, ItsNameReadsBack) {
  for (const JobKind kind : {JobKind::kRender, JobKind::kFit}) EXPECT_EQ(jobKindNamed(jobKindName(kind)), kind);
  EXPECT_EQ(jobKindName(JobKind::kFit), "fit");
  EXPECT_EQ(jobKindName(JobKind::kRender), "render");
  EXPECT_FALSE(jobKindNamed("turntable"));
  EXPECT_FALSE(jobKindNamed(""));
}

TEST(JobKind, TheDigestTextKeepsTheTagsOfBefore) {
  EXPECT_EQ((WorkRequest{JobKind::kRender, "stature=1.659"}.digestText()), "stature=1.659");
  EXPECT_EQ((WorkRequest{JobKind::kFit, "sex=female&style=pencil"}.digestText()), "fit?sex=female&style=pencil");
  EXPECT_NE((WorkRequest{JobKind::kFit, "a=1"}), (WorkRequest{JobKind::kRender, "a=1"}));  // other work
}
