#pragma once
// The output paths a user names on the command line (--junit FILE, --log FILE, --out FOLDER), checked
// before any work: a run of minutes must not end by overwriting the scenario it read, or by failing to
// write its report. docs/outputs.md states the rules.

#include <filesystem>
#include <string>
#include <vector>

namespace physltl::common {

// `file` as an output file for `option`; BadInput naming the option when it is empty, a folder, one of
// `inputs` (the same file by any name: a symlink, a hard link, "./x"), or under a path that is a file.
// A device or a FIFO is accepted (written into, not replaced), as is a symlink (written through).
std::filesystem::path checked_output_file(const std::string& option, const std::string& file,
                                          const std::vector<std::filesystem::path>& inputs);

// `folder` as an output folder for `option`; BadInput when it is empty, a file, under a path that is a file,
// one of `inputs` or inside one. Every command's --out goes through it before any work.
std::filesystem::path checked_output_folder(const std::string& option, const std::string& folder,
                                            const std::vector<std::filesystem::path>& inputs);

// The one rule for a folder a command replaces or empties (`<out>/<scenario>/`, `<out>/test/<scenario>/`, a
// shard's folder; docs/outputs.md, "Folders a command replaces"), checked before any work. BadInput (exit
// 2) naming the folder when its name is none a folder can have here (empty, ".", "..", over 240 bytes), it
// lies under /proc or /sys, it is or holds one of `inputs` (named too), or it exists holding entries that
// are neither physltl-studio's marker (kMadeHereMarker: a folder this program made) nor output names
// (kOutputNames: what a run, check, execute, bench or test writes there).
void check_replaceable(const std::filesystem::path& folder, const std::vector<std::filesystem::path>& inputs);
// The first part of that rule alone, for a folder a command only adds files to: a name a folder can have
// here, outside /proc and /sys.
void check_folder_name(const std::filesystem::path& folder);
// The file every folder this program makes to be replaced later holds.
inline constexpr const char* kMadeHereMarker = ".physltl-studio";
// Writes it into `folder`.
void mark_made_here(const std::filesystem::path& folder);

// Whether `a` and `b` name the same file or folder, existing or not.
bool same_path(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace physltl::common
