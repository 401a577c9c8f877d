#pragma once
// Writes a sequence of frames as folder/frame_00000.png, frame_00001.png, ... encoding them on worker
// threads, because PNG encoding costs several times more than drawing. Each file's bytes depend only on its
// image, never on the thread that wrote it.

#include "physltl/render/image.h"

#include <cstddef>
#include <filesystem>
#include <memory>

namespace physltl::render {

class FrameWriter {
 public:
  // threads 0: one per hardware thread. At most `max_queued` frames wait in memory; add() blocks beyond that.
  explicit FrameWriter(std::filesystem::path folder, unsigned threads = 0, std::size_t max_queued = 8);
  ~FrameWriter();  // writes what is queued; errors are reported by finish() only
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  void add(Image frame);
  void add(std::shared_ptr<const Image> frame);  // shared with another consumer, such as VideoEncoder
  // Waits until every added frame is on disk; rethrows the first error. Returns the number of frames added.
  int finish();

  // The ffmpeg pattern of these names is frame_%05d.png.
  static std::filesystem::path frame_path(const std::filesystem::path& folder, int index);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace physltl::render
