// The one way kerf replaces a file (`kerf fmt --write`, `kerf check --fix`, `--write-baseline`,
// later `kerf convert --write`): a temp file made with mkstemp in the same folder, the text
// written and fsync'ed, the old file's permissions given to it, then rename() over the old file.
// A reader sees the old file or the new one, never half a file; on any failure the temp file is
// removed and the original is untouched. A file that does not exist yet is created the same way
// (with the permissions a new file gets: 0666 less the umask).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace kerf::project {

// nullopt on success, else what went wrong, without the path ("cannot replace the file: Permission
// denied; the file is left as it was").
std::optional<std::string> write_atomically(const std::filesystem::path& path, std::string_view text);

}  // namespace kerf::project
