#pragma once
// The one way the program writes a file of its own: whole or not at all. The text goes to a temporary
// file beside the final one, which a rename puts in place; a failure leaves the final file as it was and
// removes the temporary one. JSON is written indented by two, with a final newline.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string_view>

namespace physltl::app {

enum class Durability {
  kRenamed,  // the rename makes it whole; enough for outputs a failed run replaces anyway
  kSynced,   // also flushed to the disk before the rename: campaign records that outlive a killed machine
};

// Whether `file` is what a writer killed before its rename left behind (NAME.tmp-PID).
bool is_unfinished_write(const std::filesystem::path& file);

// Throws BadInput "cannot write FILE" when the file cannot be written.
void write_text_file(const std::filesystem::path& file, std::string_view text, Durability durability = Durability::kRenamed);
void write_json_file(const std::filesystem::path& file, const nlohmann::ordered_json& json,
                     Durability durability = Durability::kRenamed);
void write_json_file(const std::filesystem::path& file, const nlohmann::json& json, Durability durability = Durability::kRenamed);

}  // namespace physltl::app
