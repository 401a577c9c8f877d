#include "physltl/render/video.h"

#include "physltl/render/frame_writer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace physltl::render {
namespace {

// Odd dimensions on purpose: H.264 with yuv420p needs even ones, which encode_video has to arrange.
std::filesystem::path folder_with_frames(const std::string& name, int count) {
  const std::filesystem::path folder = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  FrameWriter writer(folder);
  for (int i = 0; i < count; ++i) {
    Image frame(65, 49);
    for (std::size_t p = 0; p < frame.rgb.size(); ++p) frame.rgb[p] = static_cast<std::uint8_t>((p + 9 * i) % 256);
    writer.add(std::move(frame));
  }
  writer.finish();
  return folder;
}

class ScopedPath {
 public:
  explicit ScopedPath(const std::string& value) : saved_(std::getenv("PATH")) { setenv("PATH", value.c_str(), 1); }
  ~ScopedPath() { setenv("PATH", saved_.c_str(), 1); }

 private:
  std::string saved_;
};

std::vector<char> file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Video, EncodesOddSizedFramesIntoTheSameMp4BytesEveryTime) {
  const std::filesystem::path folder = folder_with_frames("video_frames", 5);
  const std::filesystem::path first = folder.parent_path() / "plan.mp4", second = folder.parent_path() / "again.mp4";
  std::filesystem::remove(first);
  const VideoResult result = encode_video(folder, 30, first);
  if (!result.written && result.message.find("not on PATH") != std::string::npos) GTEST_SKIP() << result.message;
  ASSERT_TRUE(result.written) << result.message;
  EXPECT_GT(std::filesystem::file_size(first), 0u);
  ASSERT_TRUE(encode_video(folder, 30, second).written);
  EXPECT_EQ(file_bytes(first), file_bytes(second));
}

TEST(Video, SaysFfmpegIsMissingAndKeepsTheFrames) {
  const std::filesystem::path folder = folder_with_frames("video_frames_no_ffmpeg", 2);
  const std::filesystem::path video = folder.parent_path() / "missing.mp4";
  VideoResult result;
  {
    ScopedPath empty_path(folder.string());  // a folder with no ffmpeg in it
    result = encode_video(folder, 30, video);
  }
  EXPECT_FALSE(result.written);
  EXPECT_NE(result.message.find("ffmpeg is not on PATH"), std::string::npos) << result.message;
  EXPECT_NE(result.message.find(folder.string()), std::string::npos) << result.message;
  EXPECT_FALSE(std::filesystem::exists(video));
  EXPECT_TRUE(std::filesystem::exists(FrameWriter::frame_path(folder, 1)));
}

TEST(Video, ReportsAFolderWithoutFrames) {
  const std::filesystem::path folder = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / "no_frames";
  std::filesystem::create_directories(folder);
  const VideoResult result = encode_video(folder, 30, folder / "plan.mp4");
  if (result.message.find("not on PATH") != std::string::npos) GTEST_SKIP() << result.message;
  EXPECT_FALSE(result.written);
  EXPECT_NE(result.message.find("no frames"), std::string::npos) << result.message;
}

}  // namespace
}  // namespace physltl::render
