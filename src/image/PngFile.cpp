#include "image/PngFile.h"

#include <png.h>

#include <stdexcept>

#include "io/AtomicFile.h"

namespace tabletop {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": " + what);
}

}  // namespace

// libpng's simplified API (1.6) reports errors in png_image::message
// instead of a longjmp, so no C++ object is ever jumped over.

void writePng(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != std::size_t(image.width) * image.height * 3) {
    fail(path, "cannot write an empty or malformed image");
  }
  AtomicFile file(path);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  if (!png_image_write_to_file(&png, file.temporaryPath().c_str(), 0, image.rgb.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    fail(path, "cannot write PNG: " + message);
  }
  const std::string problem = file.commit();
  if (!problem.empty()) throw std::runtime_error(problem);
}

Image readPng(const std::string& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) fail(path, std::string("cannot read PNG: ") + png.message);
  png.format = PNG_FORMAT_RGB;
  Image image(static_cast<int>(png.width), static_cast<int>(png.height));
  if (!png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    fail(path, "cannot read PNG: " + message);
  }
  return image;
}

}  // namespace tabletop
