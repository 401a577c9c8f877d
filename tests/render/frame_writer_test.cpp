#include "physltl/render/frame_writer.h"

#include "file_bytes.h"
#include "physltl/render/png.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace physltl::render {
namespace {

std::filesystem::path fresh_folder(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

Image numbered_frame(int index) {
  Image image(32, 24);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(i * index % 256);
  return image;
}

using test::file_bytes;

TEST(FrameWriter, WritesNumberedFramesWithTheBytesOfEachImage) {
  const std::filesystem::path folder = fresh_folder("frames");
  constexpr int kFrames = 20;
  FrameWriter writer(folder, 2, 3);  // a queue smaller than the frame count: add() has to wait
  for (int i = 0; i < kFrames; ++i) writer.add(numbered_frame(i));
  EXPECT_EQ(writer.finish(), kFrames);
  for (int i = 0; i < kFrames; ++i) {
    EXPECT_EQ(file_bytes(FrameWriter::frame_path(folder, i)), encode_png(numbered_frame(i))) << "frame " << i;
  }
  EXPECT_FALSE(std::filesystem::exists(FrameWriter::frame_path(folder, kFrames)));
  EXPECT_EQ(FrameWriter::frame_path(folder, 7).filename(), "frame_00007.png");
}

TEST(FrameWriter, ReportsAFailedWriteFromFinish) {
  FrameWriter writer("/nonexistent/frames", 2);
  writer.add(numbered_frame(1));
  EXPECT_THROW(writer.finish(), std::runtime_error);
}

}  // namespace
}  // namespace physltl::render
