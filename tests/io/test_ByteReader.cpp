// ByteWriter and ByteReader: values written one at a time come back in order, bit for
// bit; a read past the end says false and leaves its value alone; a count or length
// larger than what is left is refused, not allocated.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

#include "io/ByteReader.h"
#include "io/ByteWriter.h"

using figment::ByteReader;
using figment::ByteWriter;

TEST(ByteReader, GivesBackWhatWasWrittenInOrder) {
  ByteWriter out;
  out.put(std::int32_t{-7});
  out.put(std::nextafter(1.0, 2.0));
  out.put(std::array<char, 3>{'a', 'b', 'c'});
  out.putArray(std::vector<float>{0.5f, -0.0f, 3e-38f});
  out.putText("µ line\n");
  out.putArray(std::vector<std::int32_t>{});
  const std::vector<unsigned char> bytes = out.take();
  ByteReader in(bytes);
  std::int32_t i = 0;
  double d = 0.0;
  std::array<char, 3> a{};
  std::vector<float> floats;
  std::string text;
  std::vector<std::int32_t> none{1};
  ASSERT_TRUE(in.get(i) && in.get(d) && in.get(a) && in.getArray(floats) && in.getText(text) && in.getArray(none));
  EXPECT_EQ(i, -7);
  EXPECT_EQ(d, std::nextafter(1.0, 2.0));
  EXPECT_EQ(a, (std::array<char, 3>{'a', 'b', 'c'}));
  ASSERT_EQ(floats.size(), 3u);
  EXPECT_TRUE(std::signbit(floats[1]));
  EXPECT_EQ(floats[2], 3e-38f);
  EXPECT_EQ(text, "µ line\n");
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(in.done());
}

TEST(ByteReader, AReadPastTheEndSaysFalseAndLeavesTheValue) {
  ByteWriter out;
  out.put(std::uint16_t{5});
  const std::vector<unsigned char> bytes = out.take();
  ByteReader in(bytes);
  std::uint32_t wide = 42;
  EXPECT_FALSE(in.get(wide));
  EXPECT_EQ(wide, 42u);
  std::uint16_t narrow = 0;
  EXPECT_TRUE(in.get(narrow));
  EXPECT_EQ(narrow, 5);
  EXPECT_TRUE(in.done());
  EXPECT_FALSE(in.get(narrow));
}

TEST(ByteReader, ACountOrLengthBeyondTheBytesIsRefused) {
  ByteWriter out;
  out.put(std::uint64_t{1} << 60);  // a count no file of this size can hold
  out.put(std::uint32_t{0});
  const std::vector<unsigned char> bytes = out.take();
  std::vector<double> values;
  EXPECT_FALSE(ByteReader(bytes).getArray(values));
  EXPECT_TRUE(values.empty());
  std::string text;
  EXPECT_FALSE(ByteReader(bytes).getText(text));
}
