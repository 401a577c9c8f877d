#include "physltl/common/files.h"

#include "physltl/common/bad_input.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <map>
#include <mutex>
#include <set>

#include <string>

namespace physltl::common {

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

nlohmann::json parse_json(std::string_view text) {
  const nlohmann::json::parser_callback_t within_depth = [](int depth, nlohmann::json::parse_event_t event, nlohmann::json&) {
    const bool opens = event == nlohmann::json::parse_event_t::object_start || event == nlohmann::json::parse_event_t::array_start;
    if (opens && depth >= kMaxJsonDepth) {
      throw nlohmann::json::out_of_range::create(406, "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels",
                                                 static_cast<const nlohmann::json*>(nullptr));
    }
    return true;
  };
  return nlohmann::json::parse(text, within_depth);
}

nlohmann::json read_json_file(const std::filesystem::path& file, std::size_t max_bytes, const std::string& what) {
  const std::string text = read_input_file(file, max_bytes);
  try {
    return parse_json(text);
  } catch (const nlohmann::json::exception& e) {
    throw BadInput(file.string() + ": not " + what + " (" + e.what() + ")");
  }
}

bool is_unfinished_write(const std::filesystem::path& file) {
  return file.filename().string().find(".tmp-") != std::string::npos;
}

std::filesystem::path link_target(const std::filesystem::path& file) {
  std::filesystem::path target = file;
  std::error_code error;
  for (int hops = 0; std::filesystem::is_symlink(std::filesystem::symlink_status(target, error)); ++hops) {
    if (hops == 40) throw BadInput("cannot write " + file.string() + ": a loop of symbolic links");
    const std::filesystem::path link = std::filesystem::read_symlink(target, error);
    if (error) throw BadInput("cannot write " + file.string() + ": " + error.message());
    target = link.is_absolute() ? link : target.parent_path() / link;
  }
  return target;
}

namespace {

bool write_all(int fd, std::string_view text) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n <= 0) return false;
    written += static_cast<std::size_t>(n);
  }
  return true;
}

// The temporary files of writes under way, for remove_unfinished_writes(). Never destroyed: the stop
// signal's watchdog may use them while the process exits.
std::mutex& writes_mutex() {
  static auto* mutex = new std::mutex;
  return *mutex;
}
std::set<std::filesystem::path>& unfinished_writes() {
  static auto* files = new std::set<std::filesystem::path>;
  return *files;
}

// A temporary file known to remove_unfinished_writes() while it exists.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::filesystem::path path) : path_(std::move(path)) {
    const std::lock_guard lock(writes_mutex());
    unfinished_writes().insert(path_);
  }
  ~TemporaryFile() {
    const std::lock_guard lock(writes_mutex());
    unfinished_writes().erase(path_);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// A FIFO or a device (--junit /dev/stdout) is written into: it is no file to replace. A FIFO nobody
// reads is an error rather than a wait.
void write_into_stream(const std::filesystem::path& file, std::string_view text) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    throw BadInput("cannot write " + file.string() + (errno == ENXIO ? ": a pipe nobody reads" : ""));
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  const bool ok = write_all(fd, text);
  if (::close(fd) != 0 || !ok) throw BadInput("cannot write " + file.string());
}

bool ended(pid_t pid) { return pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH; }

struct Leftover {
  std::filesystem::path path;
  pid_t pid;  // of the process that left it
};

// What killed runs left in a folder: `NAME.tmp-PID` and `NAME.old-PID` whose process has ended, by NAME.
std::multimap<std::string, Leftover> leftovers_in(const std::filesystem::path& folder) {
  std::multimap<std::string, Leftover> found;
  std::error_code error;
  for (const std::filesystem::directory_entry& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    for (const std::string tag : {".tmp-", ".old-"}) {
      const std::size_t at = name.rfind(tag);
      if (at == std::string::npos || at == 0 || at + tag.size() == name.size()) continue;
      const std::string digits = name.substr(at + tag.size());
      if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
      const pid_t pid = static_cast<pid_t>(std::stol(digits));
      if (ended(pid)) found.emplace(name.substr(0, at), Leftover{entry.path(), pid});
    }
  }
  return found;
}

// Each folder is listed once per process, when it is first written into: a folder of 20,000 imported
// levels would otherwise be listed once per file written, and the import take time growing as its square.
std::mutex& leftovers_mutex() {
  static auto* mutex = new std::mutex;
  return *mutex;
}
std::map<std::filesystem::path, std::multimap<std::string, Leftover>>& leftovers_by_folder() {
  static auto* folders = new std::map<std::filesystem::path, std::multimap<std::string, Leftover>>;
  return *folders;
}

}  // namespace

void remove_unfinished_writes() {
  const std::lock_guard lock(writes_mutex());
  std::error_code ignored;
  for (const std::filesystem::path& file : unfinished_writes()) std::filesystem::remove(file, ignored);
}

void remove_leftovers_of_ended_runs(const std::filesystem::path& final_path) {
  const std::filesystem::path parent = final_path.has_parent_path() ? final_path.parent_path() : std::filesystem::path(".");
  const std::lock_guard lock(leftovers_mutex());
  auto [listed, first_time] = leftovers_by_folder().try_emplace(parent);
  if (first_time) listed->second = leftovers_in(parent);
  const auto [first, last] = listed->second.equal_range(final_path.filename().string());
  std::error_code error;
  for (auto it = first; it != last; ++it) {
    // Asked again: the listing may be hours old, and a new process may have the pid now.
    if (ended(it->second.pid)) std::filesystem::remove_all(it->second.path, error);
  }
  listed->second.erase(first, last);
}

void write_text_file(const std::filesystem::path& file, std::string_view text, Durability durability) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (std::filesystem::is_directory(status)) throw BadInput("cannot write " + file.string() + ": it is a folder");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    // Opened by its own name: /dev/stdout's links end in names such as "pipe:[1234]" only the kernel resolves.
    write_into_stream(file, text);
    return;
  }
  const std::filesystem::path target = link_target(file);
  remove_leftovers_of_ended_runs(target);
  const TemporaryFile temporary(target.string() + ".tmp-" + std::to_string(::getpid()));
  const std::filesystem::path& temp = temporary.path();
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw BadInput("cannot write " + file.string());
  bool ok = write_all(fd, text) && (durability != Durability::kSynced || ::fsync(fd) == 0);
  ok = ::close(fd) == 0 && ok;
  if (ok) std::filesystem::rename(temp, target, error);
  if (!ok || error) {
    std::filesystem::remove(temp, error);
    throw BadInput("cannot write " + file.string());
  }
}

std::string json_text(const nlohmann::ordered_json& json, int indent) {
  return json.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::string json_text(const nlohmann::json& json, int indent) {
  return json.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

void write_json_file(const std::filesystem::path& file, const nlohmann::ordered_json& json, Durability durability) {
  write_text_file(file, json_text(json, 2) + "\n", durability);
}

void write_json_file(const std::filesystem::path& file, const nlohmann::json& json, Durability durability) {
  write_text_file(file, json_text(json, 2) + "\n", durability);
}

}  // namespace physltl::common
