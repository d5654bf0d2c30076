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

namespace kerf::project {

struct ReadResult {
    std::optional<std::string> text;   // the bytes as they are on disk (decoding comes later)
    std::string error;                 // "PATH: cannot open file" when text is empty
};

class FileSystem {
public:
    virtual ~FileSystem() = default;
    virtual ReadResult read(const std::filesystem::path& path) const = 0;
    // The first `bytes` bytes (a folder walk reads only the head of each file).
    virtual ReadResult read_head(const std::filesystem::path& path, std::size_t bytes) const;
    virtual bool is_file(const std::filesystem::path& path) const = 0;
    // The regular files directly in `folder` (not in its subfolders), in path order.
    virtual std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder) const = 0;
};

// The disk. Pipes and special files are read to their end.
class DiskFileSystem : public FileSystem {
public:
    ReadResult read(const std::filesystem::path& path) const override;
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
    ReadResult read(const std::filesystem::path& path) const override;
    bool is_file(const std::filesystem::path& path) const override;
    std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder) const override;

private:
    std::shared_ptr<const FileSystem> base_;
    mutable std::shared_mutex mutex_;
    std::map<std::filesystem::path, std::string> documents_;
};

// The absolute, lexically normal form under which the index and the caches keep a path.
std::filesystem::path normal_path(const std::filesystem::path& path);

}  // namespace kerf::project
