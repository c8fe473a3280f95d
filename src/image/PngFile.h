#pragma once

#include <string>

#include "image/Image.h"

namespace tabletop {

/// Writes `image` as an 8-bit RGB PNG (libpng) to `path`, through a
/// temporary file renamed into place, so `path` is never half-written.
/// Throws std::runtime_error naming the file on failure.
void writePng(const Image& image, const std::string& path);

/// Reads a PNG of any format as 8-bit RGB. Throws
/// std::runtime_error naming the file on failure.
Image readPng(const std::string& path);

}  // namespace tabletop
