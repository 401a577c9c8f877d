#include "physltl/render/video.h"

#include "physltl/render/frame_writer.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace physltl::render {
namespace {

std::optional<std::filesystem::path> find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return candidate;
  }
  return std::nullopt;
}

struct Finished {
  int exit_code;
  std::string stderr_text;
};

// Runs a program without a shell (no quoting issues with paths), collecting what it prints on stderr.
Finished run(const std::filesystem::path& program, const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  std::string program_name = program.string();
  argv.push_back(program_name.data());
  std::vector<std::string> copies = arguments;
  for (std::string& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);

  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return {-1, "cannot create a pipe"};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, program_name.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  std::string text;
  if (spawned == 0) {
    std::array<char, 4096> buffer;
    for (ssize_t n; (n = ::read(pipe_fds[0], buffer.data(), buffer.size())) > 0;) text.append(buffer.data(), n);
  }
  ::close(pipe_fds[0]);
  if (spawned != 0) return {-1, "cannot start " + program_name};
  int status = 0;
  ::waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

}  // namespace

VideoResult encode_video(const std::filesystem::path& frames_folder, int fps, const std::filesystem::path& output) {
  const std::optional<std::filesystem::path> ffmpeg = find_on_path("ffmpeg");
  if (!ffmpeg) {
    return {false, "ffmpeg is not on PATH, so no " + output.filename().string() + " was made; the frames are in " +
                       frames_folder.string() + " (Debian: apt-get install ffmpeg)"};
  }
  if (!std::filesystem::exists(FrameWriter::frame_path(frames_folder, 0))) {
    return {false, "no frames in " + frames_folder.string() + " to encode"};
  }
  // H.264 needs even dimensions: pad odd ones by a pixel. The bitexact flags and dropped metadata make the
  // file the same bytes on every run.
  const Finished result = run(*ffmpeg, {"-nostdin", "-y", "-loglevel", "error",
                                        "-framerate", std::to_string(fps),
                                        "-i", (frames_folder / "frame_%05d.png").string(),
                                        "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                        "-c:v", "libx264", "-crf", "18", "-pix_fmt", "yuv420p",
                                        "-movflags", "+faststart", "-fflags", "+bitexact", "-flags:v", "+bitexact",
                                        "-map_metadata", "-1", output.string()});
  if (result.exit_code != 0) {
    return {false, "ffmpeg failed (exit " + std::to_string(result.exit_code) + ") making " + output.string() +
                       "; the frames are in " + frames_folder.string() + ": " + result.stderr_text};
  }
  return {true, "wrote " + output.string()};
}

}  // namespace physltl::render
