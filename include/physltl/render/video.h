#pragma once
// plan.mp4 from the frames FrameWriter wrote, through the ffmpeg command line (H.264, yuv420p, bit-exact).

#include <filesystem>
#include <string>

namespace physltl::render {

struct VideoResult {
  bool written = false;
  std::string message;  // why not, in words a user can act on (ffmpeg missing, or ffmpeg's own error)
};

// Never throws and never touches the frames: when ffmpeg is not on PATH or fails, the frames stay usable.
VideoResult encode_video(const std::filesystem::path& frames_folder, int fps, const std::filesystem::path& output);

}  // namespace physltl::render
