// ffmpeg asked to stop (render's SIGTERM while it encodes) is ended, and
// the video it was writing keeps what it held: the last whole one. Without
// the stop the same frames give a whole video.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "headless/VideoEncoder.h"
#include "image/PngFile.h"
#include "support/TempFiles.h"

namespace tabletop {
namespace {

std::string contentOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// Every file in `dir` other than the frames and the video.
int strays(const std::string& dir, const std::string& video) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    n += name.rfind("frame_", 0) != 0 && e.path() != video ? 1 : 0;
  }
  return n;
}

TEST(VideoEncoder, AStoppedEncodingLeavesThePreviousVideo) {
  if (!ffmpegAvailable()) GTEST_SKIP() << "ffmpeg is not installed";
  const testing::TempFolder folder("video_stop");
  const std::string& dir = folder.path();
  for (int k = 0; k < 60; ++k) {
    Image frame(64, 48);
    for (std::size_t i = 0; i < frame.rgb.size(); ++i) frame.rgb[i] = static_cast<std::uint8_t>(i * 7 + k * 13);
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%05d.png", k);
    writePng(frame, dir + name);
  }
  const std::string video = dir + "/v.gif";
  std::ofstream(video) << "previous";
  int asked = 0;
  const auto problem = encodeVideo(dir + "/frame_%05d.png", 30, video, {}, [&asked] { return ++asked > 0; });
  ASSERT_TRUE(problem.has_value());
  EXPECT_NE(problem->find("stopped encoding"), std::string::npos) << *problem;
  EXPECT_EQ(asked, 1);
  EXPECT_EQ(contentOf(video), "previous");
  EXPECT_EQ(strays(dir, video), 0);

  const auto whole = encodeVideo(dir + "/frame_%05d.png", 30, video, {}, [] { return false; });
  EXPECT_FALSE(whole.has_value()) << *whole;
  EXPECT_EQ(contentOf(video).rfind("GIF89a", 0), 0u);
  EXPECT_EQ(strays(dir, video), 0);
}

}  // namespace
}  // namespace tabletop
