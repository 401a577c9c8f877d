#include "physltl/render/video.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cerrno>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

extern char** environ;

namespace physltl::render {
namespace {

constexpr std::size_t kMaxQueued = 8;  // frames waiting for ffmpeg

std::optional<std::filesystem::path> find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return candidate;
  }
  return std::nullopt;
}

// A frame as YUV 4:2:0 (BT.601, limited range; chroma the mean of each 2x2 block), padded to even sizes by
// repeating the last column and row, as H.264 needs. Converting here, on the thread that feeds ffmpeg,
// costs a third of ffmpeg's swscale, halves what goes through the pipe, and measured closer to the PNG
// frames (SSIM in RGB 0.978 against swscale's 0.976, docs/rendering.md).
std::uint8_t luma_of(const std::uint8_t* p) {
  return static_cast<std::uint8_t>(((66 * p[0] + 129 * p[1] + 25 * p[2] + 128) >> 8) + 16);
}

void to_yuv420(const Image& frame, std::vector<std::uint8_t>& yuv) {
  const int w = frame.width, h = frame.height;
  const int even_w = (w + 1) / 2 * 2, even_h = (h + 1) / 2 * 2;
  const int chroma_w = even_w / 2, chroma_h = even_h / 2;
  yuv.resize(static_cast<std::size_t>(even_w) * even_h + 2 * static_cast<std::size_t>(chroma_w) * chroma_h);
  std::uint8_t* luma = yuv.data();
  std::uint8_t* cb = luma + static_cast<std::size_t>(even_w) * even_h;
  std::uint8_t* cr = cb + static_cast<std::size_t>(chroma_w) * chroma_h;
  std::vector<std::uint8_t> padded[2] = {std::vector<std::uint8_t>(3 * static_cast<std::size_t>(even_w)),
                                         std::vector<std::uint8_t>(3 * static_cast<std::size_t>(even_w))};
  // Row y of the frame, one pixel wider when the width is odd (its last pixel repeated).
  const auto row = [&](int y, int slot) -> const std::uint8_t* {
    const std::uint8_t* in = frame.rgb.data() + 3 * static_cast<std::size_t>(std::min(y, h - 1)) * w;
    if (even_w == w) return in;
    std::copy(in, in + 3 * static_cast<std::size_t>(w), padded[slot].begin());
    std::copy(in + 3 * (w - 1), in + 3 * w, padded[slot].end() - 3);
    return padded[slot].data();
  };
  // Two rows at a time: four luma samples and one chroma pair per 2x2 block.
  for (int cy = 0; cy < chroma_h; ++cy) {
    const std::uint8_t* top = row(2 * cy, 0);
    const std::uint8_t* bottom = row(2 * cy + 1, 1);
    std::uint8_t* luma_top = luma + static_cast<std::size_t>(2 * cy) * even_w;
    std::uint8_t* luma_bottom = luma_top + even_w;
    std::uint8_t* cb_row = cb + static_cast<std::size_t>(cy) * chroma_w;
    std::uint8_t* cr_row = cr + static_cast<std::size_t>(cy) * chroma_w;
    for (int cx = 0; cx < chroma_w; ++cx) {
      const std::uint8_t* a = top + 6 * cx;
      const std::uint8_t* b = bottom + 6 * cx;
      luma_top[2 * cx] = luma_of(a);
      luma_top[2 * cx + 1] = luma_of(a + 3);
      luma_bottom[2 * cx] = luma_of(b);
      luma_bottom[2 * cx + 1] = luma_of(b + 3);
      const int r = a[0] + a[3] + b[0] + b[3], g = a[1] + a[4] + b[1] + b[4], bl = a[2] + a[5] + b[2] + b[5];
      // Sums of four pixels: >> 10 is / (4 * 256).
      cb_row[cx] = static_cast<std::uint8_t>(((-38 * r - 74 * g + 112 * bl + 512) >> 10) + 128);
      cr_row[cx] = static_cast<std::uint8_t>(((112 * r - 94 * g - 18 * bl + 512) >> 10) + 128);
    }
  }
}

// Writes all of `size` bytes; false once the reader is gone.
bool write_all(int fd, const std::uint8_t* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

struct VideoEncoder::Impl {
  std::filesystem::path output;
  int width, height;
  pid_t pid = -1;
  int to_ffmpeg = -1;    // ffmpeg's stdin
  int from_ffmpeg = -1;  // ffmpeg's stderr
  std::string failure;   // why there is no ffmpeg to write to
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<std::shared_ptr<const Image>> queue;
  bool closing = false;
  bool broken = false;  // ffmpeg stopped reading
  int frames = 0;
  std::thread writer;
  std::vector<std::uint8_t> yuv;  // the writer thread's conversion buffer
  bool finished = false;

  void start(int fps) {
    const std::optional<std::filesystem::path> ffmpeg = find_on_path("ffmpeg");
    if (!ffmpeg) {
      failure = "ffmpeg is not on PATH, so no " + output.filename().string() + " was made (Debian: apt-get install ffmpeg)";
      return;
    }
    // ultrafast keeps up with drawing on one core, and at crf 18 the video matches its yuv420p input to an
    // SSIM of 0.9997; what yuv420p's halved colour loses against the RGB frames is the format's, whatever
    // the preset (docs/rendering.md).
    const std::vector<std::string> arguments = {
        ffmpeg->string(), "-y", "-loglevel", "error",
        "-f", "rawvideo", "-pix_fmt", "yuv420p",
        "-video_size", std::to_string((width + 1) / 2 * 2) + "x" + std::to_string((height + 1) / 2 * 2),
        "-framerate", std::to_string(fps), "-i", "pipe:0",
        "-c:v", "libx264", "-preset", "ultrafast", "-crf", "18", "-threads", "1",
        "-movflags", "+faststart", "-fflags", "+bitexact", "-flags:v", "+bitexact", "-map_metadata", "-1",
        output.string()};
    std::vector<char*> argv;
    std::vector<std::string> copies = arguments;
    for (std::string& a : copies) argv.push_back(a.data());
    argv.push_back(nullptr);

    int input[2], errors[2];
    if (::pipe2(input, O_CLOEXEC) != 0) {
      failure = "cannot create a pipe to ffmpeg";
      return;
    }
    if (::pipe2(errors, O_CLOEXEC) != 0) {
      ::close(input[0]);
      ::close(input[1]);
      failure = "cannot create a pipe from ffmpeg";
      return;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, input[0], STDIN_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, errors[1], STDERR_FILENO);
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(input[0]);
    ::close(errors[1]);
    if (spawned != 0) {
      ::close(input[1]);
      ::close(errors[0]);
      pid = -1;
      failure = "cannot start " + ffmpeg->string();
      return;
    }
    to_ffmpeg = input[1];
    from_ffmpeg = errors[0];
    writer = std::thread([this] { write_frames(); });
  }

  void write_frames() {
    // A write to a pipe whose reader died raises SIGPIPE in the writing thread: block it here, so the
    // write fails with EPIPE instead of ending the program.
    sigset_t pipe_signal;
    sigemptyset(&pipe_signal);
    sigaddset(&pipe_signal, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_signal, nullptr);
    std::unique_lock lock(mutex);
    for (;;) {
      changed.wait(lock, [&] { return closing || !queue.empty(); });
      if (queue.empty()) break;
      const std::shared_ptr<const Image> frame = std::move(queue.front());
      queue.pop_front();
      changed.notify_all();
      lock.unlock();
      if (!broken) to_yuv420(*frame, yuv);
      const bool ok = broken || write_all(to_ffmpeg, yuv.data(), yuv.size());
      lock.lock();
      broken = !ok;
    }
    ::close(to_ffmpeg);  // end of input: ffmpeg finishes the file
    to_ffmpeg = -1;
  }

  VideoResult finish() {
    finished = true;
    if (pid < 0) return {false, failure};
    {
      std::lock_guard lock(mutex);
      closing = true;
    }
    changed.notify_all();
    writer.join();
    std::string text;
    std::array<char, 4096> buffer;
    for (ssize_t n; (n = ::read(from_ffmpeg, buffer.data(), buffer.size())) > 0;) text.append(buffer.data(), n);
    ::close(from_ffmpeg);
    int status = 0;
    ::waitpid(pid, &status, 0);
    pid = -1;
    const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (frames == 0) return {false, "no frames to encode into " + output.string()};
    if (exit_code != 0 || broken) {
      return {false, "ffmpeg failed (exit " + std::to_string(exit_code) + ") making " + output.string() + ": " + text};
    }
    return {true, "wrote " + output.string()};
  }
};

VideoEncoder::VideoEncoder(std::filesystem::path output, int width, int height, int fps)
    : impl_(std::make_unique<Impl>()) {
  impl_->output = std::move(output);
  impl_->width = width;
  impl_->height = height;
  impl_->start(fps);
}

VideoEncoder::~VideoEncoder() {
  if (impl_->finished) return;
  if (impl_->pid > 0) ::kill(impl_->pid, SIGTERM);
  impl_->finish();
}

void VideoEncoder::add(std::shared_ptr<const Image> frame) {
  if (impl_->pid < 0) return;
  if (frame->width != impl_->width || frame->height != impl_->height) {
    throw std::invalid_argument("VideoEncoder: a frame of another size than the video's");
  }
  std::unique_lock lock(impl_->mutex);
  impl_->changed.wait(lock, [&] { return impl_->queue.size() < kMaxQueued; });
  impl_->queue.push_back(std::move(frame));
  ++impl_->frames;
  impl_->changed.notify_all();
}

VideoResult VideoEncoder::finish() { return impl_->finish(); }

}  // namespace physltl::render
