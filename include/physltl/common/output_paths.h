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

// Whether `a` and `b` name the same file or folder, existing or not.
bool same_path(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace physltl::common
