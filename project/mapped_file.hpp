// A program file mapped into memory for a streamed dry run (interpreter/loaded_file.hpp): the text
// is addressable as a whole, but only the pieces being parsed are resident; `release` hands the
// pages of a parsed range back to the kernel (they are read again from the page cache if the run
// returns there). Pipes and special files, which cannot be mapped, are read into memory instead.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace kerf::project {

class MappedFile {
public:
    // nullopt after writing the reason to `error`.
    static std::optional<MappedFile> open(const std::filesystem::path& path, std::string& error);
    MappedFile(MappedFile&& other) noexcept;
    MappedFile& operator=(MappedFile&&) = delete;
    MappedFile(const MappedFile&) = delete;
    ~MappedFile();

    std::string_view text() const { return mapped_ ? std::string_view(mapped_, size_) : std::string_view(copy_); }
    // Drops the whole pages inside [begin, end) from this process's memory.
    void release(std::size_t begin, std::size_t end) const;

private:
    MappedFile() = default;
    const char* mapped_ = nullptr;
    std::size_t size_ = 0;
    std::string copy_;
};

}  // namespace kerf::project
