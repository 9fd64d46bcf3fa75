#pragma once
// Reading and writing 8-bit RGBA PNG images, rows top-down.
#include <cstdint>
#include <string>
#include <vector>

namespace pineda::tools {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, first row is the top
};

// Returns false and fills `error` when the file cannot be read or is not a PNG.
bool readPng(const std::string& path, Image& image, std::string& error);
bool writePng(const std::string& path, const Image& image, std::string& error);

}  // namespace pineda::tools
