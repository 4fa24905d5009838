// PNG files whose bytes are their pixels: read back through libpng they hold the rows
// given (bottom row first in, top row first in the file), they carry no metadata chunk
// (name, time, program), and the same image gives the same bytes under any file name.
#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "io/PngFile.h"
#include "support/TempDir.h"

namespace {

using figment::RgbImageView;
using figment::writePng;

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A 5 x 3 image whose every pixel differs: red counts columns, green rows (bottom row 0).
std::vector<unsigned char> gradient(int width, int height) {
  std::vector<unsigned char> rgb;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      rgb.push_back(static_cast<unsigned char>(40 * x));
      rgb.push_back(static_cast<unsigned char>(90 * y));
      rgb.push_back(7);
    }
  return rgb;
}

// The chunk types of a PNG file, in order.
std::vector<std::string> chunkTypes(const std::string& bytes) {
  std::vector<std::string> types;
  for (size_t at = 8; at + 8 <= bytes.size();) {
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + at);
    const uint32_t length = uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
    types.push_back(bytes.substr(at + 4, 4));
    at += 12 + length;
  }
  return types;
}

TEST(PngFile, ReadsBackAsTheRowsGivenTopRowFirst) {
  const figment::test::TempDir dir;
  const std::vector<unsigned char> rgb = gradient(5, 3);
  const std::string path = (dir.path() / "gradient.png").string();
  ASSERT_EQ(writePng(path, RgbImageView{5, 3, rgb.data()}), "");
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&image, path.c_str())) << image.message;
  image.format = PNG_FORMAT_RGB;
  ASSERT_EQ(image.width, 5u);
  ASSERT_EQ(image.height, 3u);
  std::vector<unsigned char> read(PNG_IMAGE_SIZE(image));
  ASSERT_TRUE(png_image_finish_read(&image, nullptr, read.data(), 0, nullptr)) << image.message;
  // The file's first row is the image's top row: green 180 (row 2 from the bottom).
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      const unsigned char* p = &read[size_t(3 * (5 * y + x))];
      EXPECT_EQ(p[0], 40 * x) << x << ", " << y;
      EXPECT_EQ(p[1], 90 * (2 - y)) << x << ", " << y;
      EXPECT_EQ(p[2], 7);
    }
}

TEST(PngFile, HoldsOnlyTheImageAndTheSameImageGivesTheSameBytes) {
  const figment::test::TempDir dir;
  const std::vector<unsigned char> rgb = gradient(5, 3);
  const std::string a = (dir.path() / "a.png").string(), b = (dir.path() / "other-name.png").string();
  ASSERT_EQ(writePng(a, RgbImageView{5, 3, rgb.data()}), "");
  ASSERT_EQ(writePng(b, RgbImageView{5, 3, rgb.data()}), "");
  EXPECT_EQ(chunkTypes(bytesOf(a)), (std::vector<std::string>{"IHDR", "IDAT", "IEND"}));
  EXPECT_EQ(bytesOf(a), bytesOf(b));
  // The control: one pixel changed changes the bytes.
  std::vector<unsigned char> changed = rgb;
  changed[0] ^= 1;
  ASSERT_EQ(writePng(b, RgbImageView{5, 3, changed.data()}), "");
  EXPECT_NE(bytesOf(a), bytesOf(b));
}

TEST(PngFile, EncodedInMemoryIsTheFileWritePngWrites) {
  const figment::test::TempDir dir;
  const std::vector<unsigned char> rgb = gradient(5, 3);
  const std::string file = (dir.path() / "a.png").string();
  ASSERT_EQ(writePng(file, RgbImageView{5, 3, rgb.data()}), "");
  std::string bytes;
  ASSERT_EQ(encodePng(RgbImageView{5, 3, rgb.data()}, bytes), "");
  EXPECT_EQ(bytes, bytesOf(file));  // check-tests: bytes are the subject
  EXPECT_NE(encodePng(RgbImageView{0, 3, rgb.data()}, bytes), "");
  EXPECT_TRUE(bytes.empty());
}

TEST(PngFile, AFolderThatCannotBeMadeIsAnErrorSayingWhy) {
  const figment::test::TempDir dir;
  const std::vector<unsigned char> rgb = gradient(2, 2);
  const std::string file = dir.file("a-file", "x");
  const std::string path = file + "/out.png";
  const std::string error = writePng(path, RgbImageView{2, 2, rgb.data()});
  EXPECT_NE(error.find("Not a directory"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
