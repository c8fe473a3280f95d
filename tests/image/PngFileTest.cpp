// PNG files: what is written reads back the same, and a failed write
// leaves nothing behind.

#include <filesystem>

#include <gtest/gtest.h>
#include <unistd.h>

#include "image/PngFile.h"
#include "support/TempFiles.h"

namespace tabletop {
namespace {

TEST(PngFile, RoundTripsEveryPixel) {
  Image image(7, 5);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(i * 37);
  const std::string path = ::tabletop::testing::tempDir() + "tabletop_png_" + std::to_string(getpid()) + ".png";
  writePng(image, path);
  const Image back = readPng(path);
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.rgb, image.rgb);
  EXPECT_FALSE(std::filesystem::exists(path + ".part"));
  std::filesystem::remove(path);
}

TEST(PngFile, FlipRowsPutsTheLastRowFirst) {
  Image image(1, 3);
  image.rgb = {1, 1, 1, 2, 2, 2, 3, 3, 3};
  image.flipRows();
  EXPECT_EQ(image.rgb, (std::vector<std::uint8_t>{3, 3, 3, 2, 2, 2, 1, 1, 1}));
}

TEST(PngFile, FailuresNameTheFileAndLeaveNothing) {
  const std::string path = ::tabletop::testing::tempDir() + "no_such_directory_here/x.png";
  try {
    writePng(Image(2, 2), path);
    FAIL() << "wrote into a missing directory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_THROW(readPng(path), std::runtime_error);
  EXPECT_THROW(writePng(Image(), ::tabletop::testing::tempDir() + "empty.png"), std::runtime_error);
}

}  // namespace
}  // namespace tabletop
