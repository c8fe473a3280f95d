#pragma once

#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/Colour.h"

namespace tabletop {

/// An 8-bit RGB image, top row first (as image files store it; OpenGL reads
/// its rows bottom first, so whoever reads a framebuffer flips them).
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< width * height * 3 bytes

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0) {}

  Colour at(int column, int row) const {
    const std::size_t i = (static_cast<std::size_t>(row) * width + column) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }

  /// Reverses the order of the rows (bottom-first to top-first).
  void flipRows() {
    const std::size_t stride = static_cast<std::size_t>(width) * 3;
    for (int top = 0, bottom = height - 1; top < bottom; ++top, --bottom) {
      std::swap_ranges(rgb.begin() + top * stride, rgb.begin() + (top + 1) * stride, rgb.begin() + bottom * stride);
    }
  }

  /// Each `factor` x `factor` square of pixels averaged into one (rounded):
  /// how a frame drawn `factor` times larger is anti-aliased. The sides
  /// must be multiples of `factor`. Row by row, summed into one row of
  /// totals: a 1280 x 960 frame shrinks in about a millisecond.
  Image shrunk(int factor) const {
    Image out(width / factor, height / factor);
    const int n = factor * factor;
    const std::size_t outStride = static_cast<std::size_t>(out.width) * 3;
    std::vector<int> sums(outStride);
    for (int row = 0; row < out.height; ++row) {
      std::fill(sums.begin(), sums.end(), 0);
      for (int dy = 0; dy < factor; ++dy) {
        const std::uint8_t* from = &rgb[(static_cast<std::size_t>(row) * factor + dy) * width * 3];
        for (std::size_t c = 0; c < outStride; c += 3) {
          for (int dx = 0; dx < factor; ++dx, from += 3) {
            sums[c] += from[0];
            sums[c + 1] += from[1];
            sums[c + 2] += from[2];
          }
        }
      }
      std::uint8_t* to = &out.rgb[static_cast<std::size_t>(row) * outStride];
      for (std::size_t k = 0; k < outStride; ++k) to[k] = static_cast<std::uint8_t>((sums[k] + n / 2) / n);
    }
    return out;
  }
};

}  // namespace tabletop
