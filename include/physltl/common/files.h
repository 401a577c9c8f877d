#pragma once
// The one way the program reads a file it is given and writes a file of its own. Reading takes regular
// files only, up to a size: a folder, a FIFO or a device given for a file is refused, not waited on or
// read until memory runs out. Writing is whole or not at all: the text goes to a temporary file beside the
// final one, which a rename puts in place; a failure leaves the final file as it was and removes the
// temporary one. JSON is written indented by two, with a final newline.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string_view>

namespace physltl::common {

enum class Durability {
  kRenamed,  // the rename makes it whole; enough for outputs a failed run replaces anyway
  kSynced,   // also flushed to the disk before the rename: campaign records that outlive a killed machine
};

// The bytes of `file`, a regular file of at most `max_bytes`; BadInput naming it otherwise ("is a folder,
// not a file", "is not a regular file", "is larger than 16 MiB", "cannot be read").
std::string read_input_file(const std::filesystem::path& file, std::size_t max_bytes);
// The same parsed as JSON (parse_json); BadInput naming the file and `what` it should be when it is not.
nlohmann::json read_json_file(const std::filesystem::path& file, std::size_t max_bytes, const std::string& what);

// The deepest nesting of arrays and objects the program reads back: far beyond what it writes (plan.json
// nests 4 deep), and shallow enough that copying, comparing, diffing and printing a value, which recurse,
// stay well within the stack.
inline constexpr int kMaxJsonDepth = 64;
// `text` as JSON. Throws nlohmann::json::exception for text that is not JSON, and nlohmann::json::out_of_range
// for a value nested deeper than kMaxJsonDepth, refused while it is parsed (the parser does not recurse),
// before anything copies it.
nlohmann::json parse_json(std::string_view text);

// What writing `file` replaces: the file a chain of symbolic links ends at (written through, the links
// kept), or `file` itself. Throws BadInput on a loop of links.
std::filesystem::path link_target(const std::filesystem::path& file);

// Removes the `NAME.tmp-PID` and `NAME.old-PID` siblings of `final_path` whose process had ended when this
// process first wrote into their folder: what a run killed before it could clean up left. Every writer
// calls it before writing.
void remove_leftovers_of_ended_runs(const std::filesystem::path& final_path);

// Removes the temporary files of writes under way in this process: for a process that must end at once.
void remove_unfinished_writes();

// Whether `file` is what a writer killed before its rename left behind (NAME.tmp-PID).
bool is_unfinished_write(const std::filesystem::path& file);

// JSON as text, compact (indent -1) or indented. A name from the user's input (a file name) need not be
// UTF-8, which JSON must be: such bytes become U+FFFD instead of an exception.
std::string json_text(const nlohmann::ordered_json& json, int indent = -1);
std::string json_text(const nlohmann::json& json, int indent = -1);

// Throws BadInput "cannot write FILE" when the file cannot be written. A FIFO or a device is written
// into; a symbolic link is written through (the file it ends at is replaced, the link kept).
void write_text_file(const std::filesystem::path& file, std::string_view text, Durability durability = Durability::kRenamed);
void write_json_file(const std::filesystem::path& file, const nlohmann::ordered_json& json,
                     Durability durability = Durability::kRenamed);
void write_json_file(const std::filesystem::path& file, const nlohmann::json& json, Durability durability = Durability::kRenamed);

}  // namespace physltl::common
