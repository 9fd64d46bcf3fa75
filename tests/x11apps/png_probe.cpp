// png_probe FILE X Y [X Y ...]: prints the colour of each pixel (X, Y from the top-left) of a
// PNG as RRGGBB hex, one per line. Exit 2 when the file cannot be read or a pixel is outside.
#include <png.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 4 || argc % 2 != 0) {
    std::fprintf(stderr, "usage: png_probe FILE X Y [X Y ...]\n");
    return 2;
  }
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, argv[1])) {
    std::fprintf(stderr, "%s: %s\n", argv[1], image.message);
    return 2;
  }
  image.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> rgb(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr)) {
    std::fprintf(stderr, "%s: %s\n", argv[1], image.message);
    return 2;
  }
  for (int i = 2; i + 1 < argc; i += 2) {
    const long x = std::strtol(argv[i], nullptr, 10), y = std::strtol(argv[i + 1], nullptr, 10);
    if (x < 0 || y < 0 || x >= static_cast<long>(image.width) || y >= static_cast<long>(image.height)) {
      std::fprintf(stderr, "(%ld, %ld) is outside the %ux%u image\n", x, y, image.width, image.height);
      return 2;
    }
    const unsigned char* p = &rgb[(static_cast<size_t>(y) * image.width + x) * 3];
    std::printf("%02x%02x%02x\n", p[0], p[1], p[2]);
  }
  return 0;
}
