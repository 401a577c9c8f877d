#pragma once
// plan.mp4, encoded while the frames are drawn: frames converted to YUV 4:2:0 go through a pipe to the
// ffmpeg command line (H.264 ultrafast, crf 18; quality measured in docs/rendering.md). One encoder
// thread and bit-exact flags: the same frames give the same file bytes on every run.

#include "physltl/render/image.h"

#include <filesystem>
#include <memory>
#include <string>

namespace physltl::render {

struct VideoResult {
  bool written = false;
  std::string message;  // why not, in words a user can act on (ffmpeg missing, or ffmpeg's own error)
};

class VideoEncoder {
 public:
  // Starts ffmpeg; never throws for a missing or failing ffmpeg: finish() says what happened.
  VideoEncoder(std::filesystem::path output, int width, int height, int fps);
  ~VideoEncoder();  // stops ffmpeg if finish() was not called
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Queues a frame of the size given above for the encoder (a few frames wait at most; add() blocks
  // beyond that, so drawing and encoding run side by side). Shared, not copied: FrameWriter has it too.
  void add(std::shared_ptr<const Image> frame);
  // Ends the video and waits for ffmpeg. Never throws.
  VideoResult finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace physltl::render
