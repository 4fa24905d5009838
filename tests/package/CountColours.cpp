// Counts a PNG's pixels by their dominant colour, for the package test's picture of
// examples/sphere-drape.iv: the cloth is red, the ball green.
//   figment_count_colours IMAGE.png MIN_RED MIN_GREEN
// prints "red R green G of N" and exits 0 when R >= MIN_RED and G >= MIN_GREEN.
#include <Inventor/SbImage.h>
#include <Inventor/SoDB.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s IMAGE.png MIN_RED MIN_GREEN\n", argv[0]);
    return 2;
  }
  SoDB::init();  // Coin's image readers
  SbImage image;
  if (!image.readFile(argv[1])) {
    std::fprintf(stderr, "%s: not an image Coin reads\n", argv[1]);
    return 1;
  }
  SbVec2s size;
  int bytesPerPixel = 0;
  const unsigned char* data = image.getValue(size, bytesPerPixel);
  if (!data || bytesPerPixel < 3) return 1;
  int red = 0, green = 0;
  const int pixels = size[0] * size[1];
  for (int i = 0; i < pixels; ++i) {
    const int r = data[i * bytesPerPixel], g = data[i * bytesPerPixel + 1], b = data[i * bytesPerPixel + 2];
    red += r > g + 40 && r > b + 40;  // lit or in shade
    green += g > r + 30 && g > b + 20;
  }
  std::printf("red %d green %d of %d\n", red, green, pixels);
  return red >= std::atoi(argv[2]) && green >= std::atoi(argv[3]) ? 0 : 1;
}
