// Coin's messages as a front end prints them: one line each, after the front end's prefix,
// with the noise every headless program meets left out. Coin posts through the handlers the
// way it posts its own warnings (SoDebugError::postWarning), and stderr is read back.
#include <Inventor/SoDB.h>
#include <Inventor/errors/SoDebugError.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "headless/CoinMessages.h"

namespace test_CoinMessages {

namespace {

constexpr const char* kPrefix = "figment-test: warning: ";

std::string printedFor(const char* source, const char* message) {
  testing::internal::CaptureStderr();
  SoDebugError::postWarning(source, "%s", message);
  return testing::internal::GetCapturedStderr();
}

class CoinMessagesTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    SoDB::init();
    figment::CoinMessages::install(kPrefix);
  }
};

TEST_F(CoinMessagesTest, PrintsAMessageOfSeveralLinesAsOneLineAfterThePrefix) {
  const std::string printed = printedFor("Somewhere::method", "first part\nsecond part");
  EXPECT_EQ(printed.rfind(kPrefix, 0), 0u) << printed;
  EXPECT_EQ(std::count(printed.begin(), printed.end(), '\n'), 1) << printed;
  EXPECT_NE(printed.find("first part"), std::string::npos) << printed;
  EXPECT_NE(printed.find("second part"), std::string::npos) << printed;
}

TEST_F(CoinMessagesTest, LeavesOutTheGlxQuestionAndTheEnginesOwnError) {
  // Coin asks GLX about a context OSMesa made; a ClothEngine's error is its lastError().
  EXPECT_EQ(printedFor("glxglue_isdirect", "no GLX context"), "");
  EXPECT_EQ(printedFor("ClothEngine::evaluate", "the drape failed"), "");
  // The control: the same capture shows any other source.
  EXPECT_NE(printedFor("ClothEngine::other", "shown"), "");
}

TEST_F(CoinMessagesTest, ASecondInstallKeepsTheFirstPrefix) {
  figment::CoinMessages::install("another program: ");
  EXPECT_EQ(printedFor("Somewhere::method", "text").rfind(kPrefix, 0), 0u);
}

}  // namespace

}  // namespace test_CoinMessages
