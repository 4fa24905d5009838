// What both requests are made of: canonical text splits back into the pairs it was written
// from, a number is plain decimal text and nothing else, a refusal shows the value as text
// cut to 64 bytes, and a name or value that is not UTF-8 is refused as such.

#include <gtest/gtest.h>

#include "serve/request/RequestParameters.h"

using namespace figment::serve;

TEST(RequestParameters, SplitsCanonicalTextIntoItsPairs) {
  EXPECT_EQ(RequestParameters::split("sex=female&style=pencil&x=&y"),
            (QueryParameters{{"sex", "female"}, {"style", "pencil"}, {"x", ""}, {"y", ""}}));
  EXPECT_EQ(RequestParameters::split(""), QueryParameters{});
  EXPECT_EQ(RequestParameters::split("view=0.0,10.0"), (QueryParameters{{"view", "0.0,10.0"}}));
}

TEST(RequestParameters, ANumberIsPlainDecimalTextOnly) {
  double value = 0;
  EXPECT_TRUE(RequestParameters::number("1.659", value));
  EXPECT_EQ(value, 1.659);
  EXPECT_TRUE(RequestParameters::number("-12", value));
  EXPECT_EQ(value, -12);
  for (const char* text : {"", "1e3", "0x10", "1.0 ", " 1", "inf", "nan", "1,5", "123456789012345678901234567890123"})
    EXPECT_FALSE(RequestParameters::number(text, value)) << text;
}

TEST(RequestParameters, ARefusalShowsTheValueAsTextCutTo64Bytes) {
  const ParameterError error = RequestParameters::refusal("skin", std::string(100, 'a'), "not a skin tone", "rrggbb");
  EXPECT_EQ(error.parameter, "skin");
  EXPECT_EQ(error.value, std::string(64, 'a'));
  EXPECT_EQ(error.error, "not a skin tone");
  EXPECT_EQ(error.accepted, "rrggbb");
  EXPECT_EQ(RequestParameters::refusal("skin", "\xff", "x", "y").value, "%FF");  // bytes shown encoded
}

TEST(RequestParameters, ANameOrValueThatIsNotUtf8IsRefusedAsSuch) {
  EXPECT_FALSE(RequestParameters::textError("skin", "caf\xc3\xa9"));
  const std::optional<ParameterError> value = RequestParameters::textError("skin", "caf\xe9");
  ASSERT_TRUE(value);
  EXPECT_EQ(value->error, "not UTF-8");
  EXPECT_EQ(value->parameter, "skin");
  const std::optional<ParameterError> name = RequestParameters::textError("sk\xe9n", "x");
  ASSERT_TRUE(name);
  EXPECT_EQ(name->error, "a parameter name that is not UTF-8");
  EXPECT_EQ(name->parameter, "sk%E9n");
}

TEST(RequestParameters, Utf8PrefixCutsBeforeACharacterThatWouldNotFitWhole) {
  const std::string euros = "\xe2\x82\xac\xe2\x82\xac";  // two 3-byte characters
  EXPECT_EQ(utf8Prefix(euros, 4), "\xe2\x82\xac");
  EXPECT_EQ(utf8Prefix(euros, 6), euros);
  EXPECT_EQ(utf8Prefix("abc", 2), "ab");
}
