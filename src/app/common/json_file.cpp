#include "json_file.h"

#include "bad_input.h"

#include <fcntl.h>
#include <unistd.h>

#include <string>

namespace physltl::app {

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
