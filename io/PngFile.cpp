#include "io/PngFile.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "io/AtomicFile.h"

namespace figment {

namespace {

// libpng reports through longjmp; the message is kept for the caller's one line.
void onPngError(png_structp png, png_const_charp message) {
  auto* error = static_cast<std::string*>(png_get_error_ptr(png));
  *error = message;
  png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}

// Writes the image's rows to an open file; "" on success.
std::string writeRows(std::FILE* file, const RgbImageView& image) {
  std::string error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, onPngError, onPngWarning);
  if (!png) return "cannot start the PNG writer";
  png_infop info = png_create_info_struct(png);
  std::vector<png_bytep> rows(size_t(image.height));
  const size_t stride = size_t(3) * size_t(image.width);
  for (int y = 0; y < image.height; ++y)
    rows[size_t(y)] = const_cast<png_bytep>(image.bottomRowFirst + stride * size_t(image.height - 1 - y));
  if (info && setjmp(png_jmpbuf(png)) == 0) {
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
  } else if (error.empty()) {
    error = "cannot start the PNG writer";
  }
  png_destroy_write_struct(&png, info ? &info : nullptr);
  return error;
}

}  // namespace

std::string writePng(const std::string& path, const RgbImageView& image) {
  if (image.width <= 0 || image.height <= 0 || !image.bottomRowFirst) return "no image to write";
  return writeAtomically(path, [&image](const std::string& temporary) -> std::string {
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) return std::string("cannot write the image: ") + std::strerror(errno);
    std::string error = writeRows(file, image);
    if (std::fflush(file) != 0 && error.empty()) error = std::string("cannot write the image: ") + std::strerror(errno);
    if (std::fclose(file) != 0 && error.empty()) error = std::string("cannot write the image: ") + std::strerror(errno);
    return error;
  });
}

std::string encodePng(const RgbImageView& image, std::string& bytes) {
  bytes.clear();
  if (image.width <= 0 || image.height <= 0 || !image.bottomRowFirst) return "no image to write";
  // A FILE over a growing buffer (POSIX open_memstream), so the rows go through the same
  // writer as a file's: the same picture gives the same bytes either way.
  char* buffer = nullptr;
  size_t length = 0;
  std::FILE* stream = open_memstream(&buffer, &length);
  if (!stream) return std::string("cannot encode the image: ") + std::strerror(errno);
  std::string error = writeRows(stream, image);
  if (std::fclose(stream) != 0 && error.empty())
    error = std::string("cannot encode the image: ") + std::strerror(errno);
  if (error.empty()) bytes.assign(buffer, length);
  std::free(buffer);
  return error;
}

}  // namespace figment
