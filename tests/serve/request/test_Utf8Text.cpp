// What the service's answers show of a client's text: well-formed UTF-8 as it is, anything
// else percent-encoded, cut to a bound only between whole characters (or escapes).

#include <gtest/gtest.h>

#include "serve/request/Utf8Text.h"

using figment::serve::Utf8Text;

TEST(Utf8Text, TellsWellFormedUtf8FromEverythingElse) {
  for (const char* text : {"", "stature", "\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x91\x97", "\xed\x9f\xbf",
                           "\xee\x80\x80", "\xf4\x8f\xbf\xbf"})
    EXPECT_TRUE(Utf8Text::valid(text)) << Utf8Text::percentEncoded(text);
  // A lone continuation byte, bytes never in UTF-8, overlong forms (of NUL, '/', U+07FF,
  // U+FFFF), surrogates, past U+10FFFF, and sequences cut short.
  for (const char* text : {"\x80", "\xff", "\xfe", "\xc0\x80", "\xc1\xbf", "\xe0\x9f\xbf", "\xf0\x8f\xbf\xbf",
                           "\xed\xa0\x80", "\xed\xbf\xbf", "\xf4\x90\x80\x80", "\xf5\x80\x80\x80", "\xc3", "\xe2\x82",
                           "\xf0\x9f\x91", "a\xc3(", "\xe2\x28\xa1"})
    EXPECT_FALSE(Utf8Text::valid(text)) << Utf8Text::percentEncoded(text);
}

TEST(Utf8Text, PercentEncodesAllButPrintableAscii) {
  EXPECT_EQ(Utf8Text::percentEncoded("a b%c\xff\x01~"), "a%20b%25c%FF%01~");
  EXPECT_EQ(Utf8Text::percentEncoded(std::string("\0", 1)), "%00");
}

TEST(Utf8Text, ShowsTextAsItIsAndBytesEncoded) {
  EXPECT_EQ(Utf8Text::shown("1.70", 64), "1.70");
  EXPECT_EQ(Utf8Text::shown("caf\xc3\xa9", 64), "caf\xc3\xa9");
  EXPECT_EQ(Utf8Text::shown("\xff", 64), "%FF");
  EXPECT_EQ(Utf8Text::shown("caf\xc3\xa9\xff", 64), "caf%C3%A9%FF");  // one bad byte: all of it escaped
}

TEST(Utf8Text, CutsBetweenWholeCharactersAndEscapes) {
  EXPECT_EQ(Utf8Text::shown("abc\xc3\xa9", 4), "abc");  // é would pass 4 bytes
  EXPECT_EQ(Utf8Text::shown("abc\xc3\xa9", 5), "abc\xc3\xa9");
  EXPECT_EQ(Utf8Text::shown("\xf0\x9f\x91\x97\xf0\x9f\x91\x97", 7), "\xf0\x9f\x91\x97");
  EXPECT_EQ(Utf8Text::shown("a\xff\xff", 3), "a");  // "a%FF%FF": a cut inside an escape drops it
  EXPECT_EQ(Utf8Text::shown("a\xff\xff", 4), "a%FF");
  EXPECT_EQ(Utf8Text::shown("a\xff\xff", 5), "a%FF");
  EXPECT_EQ(Utf8Text::shown("a\xff\xff", 7), "a%FF%FF");
  for (size_t most = 0; most < 12; ++most) {
    const std::string cut = Utf8Text::shown("\xe2\x82\xac\xe2\x82\xac\xe2\x82\xac", most);
    EXPECT_TRUE(Utf8Text::valid(cut));
    EXPECT_LE(cut.size(), most);
    EXPECT_EQ(cut.size(), most / 3 * 3);
  }
}
