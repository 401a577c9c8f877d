#include "files.h"

#include "bad_input.h"

#include <fcntl.h>
#include <unistd.h>

#include <string>

namespace physltl::app {

std::string read_input_file(const std::filesystem::path& file, std::size_t max_bytes) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (error || !std::filesystem::exists(status)) throw BadInput(file.string() + ": no such file");
  if (std::filesystem::is_directory(status)) throw BadInput(file.string() + ": is a folder, not a file");
  if (!std::filesystem::is_regular_file(status)) throw BadInput(file.string() + ": is not a regular file (a device or a pipe?)");
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw BadInput(file.string() + ": cannot be read");
  std::string text;
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n <= 0) {
      ::close(fd);
      if (n < 0) throw BadInput(file.string() + ": cannot be read");
      return text;
    }
    if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
      ::close(fd);
      throw BadInput(file.string() + ": is larger than " + std::to_string(max_bytes >> 20) + " MiB");
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
}

nlohmann::json read_json_file(const std::filesystem::path& file, std::size_t max_bytes, const std::string& what) {
  const std::string text = read_input_file(file, max_bytes);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw BadInput(file.string() + ": not " + what + " (" + e.what() + ")");
  }
}

bool is_unfinished_write(const std::filesystem::path& file) {
  return file.filename().string().find(".tmp-") != std::string::npos;
}

void write_text_file(const std::filesystem::path& file, std::string_view text, Durability durability) {
  const std::filesystem::path temp = file.string() + ".tmp-" + std::to_string(::getpid());
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw BadInput("cannot write " + file.string());
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  bool ok = written == text.size() && (durability != Durability::kSynced || ::fsync(fd) == 0);
  ok = ::close(fd) == 0 && ok;
  std::error_code error;
  if (ok) std::filesystem::rename(temp, file, error);
  if (!ok || error) {
    std::filesystem::remove(temp, error);
    throw BadInput("cannot write " + file.string());
  }
}

void write_json_file(const std::filesystem::path& file, const nlohmann::ordered_json& json, Durability durability) {
  write_text_file(file, json.dump(2) + "\n", durability);
}

void write_json_file(const std::filesystem::path& file, const nlohmann::json& json, Durability durability) {
  write_text_file(file, json.dump(2) + "\n", durability);
}

}  // namespace physltl::app
