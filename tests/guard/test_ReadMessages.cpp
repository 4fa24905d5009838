// Coin's messages while the guard reads: read errors as one line each with their line,
// warnings held until passed on, and the handlers found put back afterwards.
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/ReadMessages.h"

using figment::guard::ReadMessages;

namespace {

std::vector<std::string> posted;

void collect(const SoError* error, void*) {
  posted.emplace_back(error->getDebugString().getString());
}

TEST(ReadMessages, OneLineDropsCoinsPrefixAndJoinsTheLines) {
  EXPECT_EQ(ReadMessages::oneLine("Coin read error: Unknown node type\n\tOccurred here\n"),
            "Unknown node type; Occurred here");
  EXPECT_EQ(ReadMessages::oneLine("Coin warning in SoFile::readNamedFile(): cannot open\n"), "cannot open");
  EXPECT_EQ(ReadMessages::oneLine("plain text"), "plain text");
}

TEST(ReadMessages, CollectsReadErrorsWithTheirLineAndPutsTheHandlersBack) {
  SoDB::init();
  SoDebugError::setHandlerCallback(collect, nullptr);
  SoReadError::setHandlerCallback(collect, nullptr);
  posted.clear();
  std::vector<std::string> errors;
  {
    ReadMessages messages;
    static const char kScene[] = "#Inventor V2.1 ascii\n\nSeparator {\n  NoSuchNode { }\n}\n";
    SoInput in;
    in.setBuffer(kScene, sizeof kScene - 1);
    SoSeparator* root = SoDB::readAll(&in);
    EXPECT_EQ(root, nullptr);
    errors = messages.readErrors("");
  }
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(errors[0].rfind("line 4: ", 0), 0u) << errors[0];
  EXPECT_NE(errors[0].find("NoSuchNode"), std::string::npos) << errors[0];
  EXPECT_EQ(errors[0].find('\n'), std::string::npos) << errors[0];
  EXPECT_TRUE(posted.empty());  // taken by the guard, not passed on
  EXPECT_EQ(SoReadError::getHandlerCallback(), collect);
  EXPECT_EQ(SoDebugError::getHandlerCallback(), collect);
}

TEST(ReadMessages, HoldsWarningsUntilPassedOn) {
  SoDB::init();
  SoDebugError::setHandlerCallback(collect, nullptr);
  posted.clear();
  {
    ReadMessages messages;
    SoDebugError::postWarning("Somewhere::method", "held");
    EXPECT_TRUE(posted.empty());
    messages.passOnWarnings();
  }
  ASSERT_EQ(posted.size(), 1u);
  EXPECT_NE(posted[0].find("held"), std::string::npos) << posted[0];
  EXPECT_NE(posted[0].find("Somewhere::method"), std::string::npos) << posted[0];
}

}  // namespace
