#pragma once

// Finding an entity's colour in a rendered image. Lighting and shadows
// scale a surface's colour, so pixels are matched by chromaticity (each
// channel's share of the sum), which scaling keeps, and a floor on
// brightness.

#include <cmath>
#include <functional>

#include "core/Colour.h"
#include "image/Image.h"

namespace tabletop::test {

// Largest distance between chromaticities that still counts as the colour.
constexpr double kChromaTolerance = 0.05;
// Darker pixels (channel sum below this) are too dark to tell apart.
constexpr int kDarkest = 60;

inline bool looksLike(const Colour& pixel, const Colour& colour) {
  const int sp = pixel.r + pixel.g + pixel.b, sc = colour.r + colour.g + colour.b;
  if (sp < kDarkest || sc == 0) return false;
  const double dr = double(pixel.r) / sp - double(colour.r) / sc;
  const double dg = double(pixel.g) / sp - double(colour.g) / sc;
  const double db = double(pixel.b) / sp - double(colour.b) / sc;
  return std::sqrt(dr * dr + dg * dg + db * db) < kChromaTolerance;
}

// The pixels of one colour inside a rectangle of an image.
struct Blob {
  int count = 0;
  double column = 0.0, row = 0.0;  // centroid
  int top = 0, bottom = -1;        // rows spanned
  int left = 0, right = -1;        // columns spanned
};

// Pixels that look like `colour` within [left, right] x [top, bottom]
// (clipped to the image), and, when given, for which `keep(column, row)`.
inline Blob findColour(const Image& image, const Colour& colour, int left = 0, int top = 0, int right = 1 << 30,
                       int bottom = 1 << 30, const std::function<bool(int, int)>& keep = {}) {
  Blob b;
  b.top = 1 << 30, b.left = 1 << 30;
  for (int row = std::max(0, top); row <= std::min(bottom, image.height - 1); ++row) {
    for (int column = std::max(0, left); column <= std::min(right, image.width - 1); ++column) {
      if (!looksLike(image.at(column, row), colour)) continue;
      if (keep && !keep(column, row)) continue;
      ++b.count;
      b.column += column, b.row += row;
      b.top = std::min(b.top, row), b.bottom = std::max(b.bottom, row);
      b.left = std::min(b.left, column), b.right = std::max(b.right, column);
    }
  }
  if (b.count > 0) b.column /= b.count, b.row /= b.count;
  return b;
}

}  // namespace tabletop::test
