// The file-system seam of the project layer. Everything above it (configuration lookup, dialect
// and machine resolution, the program index, the loader of subprograms) reads through a
// FileSystem, so the language server can lay its open documents over the disk
// (OverlayFileSystem) and tests can use a folder in memory. The only I/O of project/ is here,
// in project/walk.cpp (listing folders) and project/writer.cpp (replacing files).
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <shared_mutex>
#include <string>
#include <vector>

#include "ast/input.hpp"

namespace kerf::project {

// A file's text as kerf reads it: the bytes through the input decoder (ast/input.hpp), so every
// command and the language server refuse the same files (binary, over a size limit) and read the
// same text (UTF-16/32 transcoded, a lone CR a line break).
struct ReadResult {
    std::optional<std::string> text;           // UTF-8; nullopt when the file cannot be read or is refused
    std::string error;                         // then: "PATH: cannot open file", or the decoder's refusal with its hint
    ast::Encoding encoding = ast::Encoding::utf8;   // of the file: writers put the text back in it
    bool bom = false;
    std::vector<ast::InputProblem> problems;   // the decoder's: its refusal, or notes on a file it read (empty, UTF-16)
};

class FileSystem {
public:
    virtual ~FileSystem() = default;
    // The file decoded under `limits` (sizes per file and per line).
    virtual ReadResult read(const std::filesystem::path& path, const ast::InputLimits& limits) const = 0;
    // Under the default limits (configuration, dialect and machine files).
    ReadResult read(const std::filesystem::path& path) const { return read(path, ast::InputLimits{}); }
    // The first `bytes` bytes, decoded when they are UTF-16/32 (a folder walk reads only the head of
    // each file; a binary head is returned as it is, for recognition to refuse).
    virtual ReadResult read_head(const std::filesystem::path& path, std::size_t bytes) const;
    virtual bool is_file(const std::filesystem::path& path) const = 0;
    // The regular files directly in `folder` (not in its subfolders), in path order.
    virtual std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder) const = 0;
};

// The disk. Pipes and special files are read to their end.
class DiskFileSystem : public FileSystem {
public:
    using FileSystem::read;
    // A file over limits.max_file_bytes is refused before it is read.
    ReadResult read(const std::filesystem::path& path, const ast::InputLimits& limits) const override;
    ReadResult read_head(const std::filesystem::path& path, std::size_t bytes) const override;
    bool is_file(const std::filesystem::path& path) const override;
    std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder) const override;
};

// Documents held in memory (an editor's open buffers) over another file system: a document hides
// the file of the same path, and a document without a file on disk is listed in its folder.
class OverlayFileSystem : public FileSystem {
public:
    explicit OverlayFileSystem(std::shared_ptr<const FileSystem> base) : base_(std::move(base)) {}
    void set(const std::filesystem::path& path, std::string text);
    void remove(const std::filesystem::path& path);   // the file on disk shows again
    using FileSystem::read;
    // A document is the editor's text (already decoded); a file is read from the base.
    ReadResult read(const std::filesystem::path& path, const ast::InputLimits& limits) const override;
    bool is_file(const std::filesystem::path& path) const override;
    std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder) const override;

private:
    std::shared_ptr<const FileSystem> base_;
    mutable std::shared_mutex mutex_;
    std::map<std::filesystem::path, std::string> documents_;
};

// The decoder's verdict on `bytes` read from `path` (what DiskFileSystem::read does after reading).
ReadResult decode_file(const std::filesystem::path& path, std::string bytes, const ast::InputLimits& limits);

// The ReadResult of a file the decoder refuses for `problem` (an error).
ReadResult refusal(const std::filesystem::path& path, ast::InputProblem problem);

// The absolute, lexically normal form under which the index and the caches keep a path.
std::filesystem::path normal_path(const std::filesystem::path& path);

}  // namespace kerf::project
