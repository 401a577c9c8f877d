#include "physltl/render/video.h"

#include "file_bytes.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace physltl::render {
namespace {

std::vector<Image> frames(int count, int width = 65, int height = 49) {
  std::vector<Image> out;
  for (int i = 0; i < count; ++i) {
    Image frame(width, height);
    for (std::size_t p = 0; p < frame.rgb.size(); ++p) frame.rgb[p] = static_cast<std::uint8_t>((p + 9 * i) % 256);
    out.push_back(std::move(frame));
  }
  return out;
}

std::filesystem::path output(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / "video";
  std::filesystem::create_directories(folder);
  std::filesystem::remove(folder / name);
  return folder / name;
}

VideoResult encode(const std::vector<Image>& images, const std::filesystem::path& file) {
  VideoEncoder encoder(file, images.empty() ? 64 : images[0].width, images.empty() ? 48 : images[0].height, 30);
  for (const Image& image : images) encoder.add(std::make_shared<const Image>(image));
  return encoder.finish();
}

class ScopedPath {
 public:
  explicit ScopedPath(const std::string& value) : saved_(std::getenv("PATH")) { setenv("PATH", value.c_str(), 1); }
  ~ScopedPath() { setenv("PATH", saved_.c_str(), 1); }

 private:
  std::string saved_;
};

using test::file_bytes;

// Odd dimensions on purpose: H.264 with yuv420p needs even ones, which the encoder has to arrange.
TEST(Video, EncodesOddSizedFramesIntoTheSameMp4BytesEveryTime) {
  const std::vector<Image> images = frames(5);
  const std::filesystem::path first = output("plan.mp4"), second = output("again.mp4");
  const VideoResult result = encode(images, first);
  if (!result.written && result.message.find("not on PATH") != std::string::npos) GTEST_SKIP() << result.message;
  ASSERT_TRUE(result.written) << result.message;
  EXPECT_GT(std::filesystem::file_size(first), 0u);
  ASSERT_TRUE(encode(images, second).written);
  EXPECT_EQ(file_bytes(first), file_bytes(second));
}

TEST(Video, SaysFfmpegIsMissing) {
  const std::filesystem::path video = output("missing.mp4");
  VideoResult result;
  {
    ScopedPath empty_path(video.parent_path().string());  // a folder with no ffmpeg in it
    result = encode(frames(2), video);
  }
  EXPECT_FALSE(result.written);
  EXPECT_NE(result.message.find("ffmpeg is not on PATH"), std::string::npos) << result.message;
  EXPECT_FALSE(std::filesystem::exists(video));
}

TEST(Video, ReportsAVideoWithoutFrames) {
  const VideoResult result = encode({}, output("empty.mp4"));
  if (result.message.find("not on PATH") != std::string::npos) GTEST_SKIP() << result.message;
  EXPECT_FALSE(result.written);
  EXPECT_NE(result.message.find("no frames"), std::string::npos) << result.message;
}

TEST(Video, AFrameOfAnotherSizeIsRefused) {
  VideoEncoder encoder(output("sizes.mp4"), 64, 48, 30);
  const VideoResult probe = VideoEncoder(output("probe.mp4"), 64, 48, 30).finish();
  if (probe.message.find("not on PATH") != std::string::npos) GTEST_SKIP() << probe.message;
  EXPECT_THROW(encoder.add(std::make_shared<const Image>(32, 48)), std::invalid_argument);
}

}  // namespace
}  // namespace physltl::render
