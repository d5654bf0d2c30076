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
#include <vector>

#include "ast/input.hpp"
#include "project/files.hpp"

namespace kerf::project {

class MappedFile {
public:
    // nullopt after writing to `failure` why: the file cannot be read (its `error`), or the input
    // decoder (ast/input.hpp) refuses it (its `problems` too). The decoder sees the mapped bytes in
    // windows whose pages are dropped behind it; a UTF-16/32 file is decoded into memory instead.
    static std::optional<MappedFile> open(const std::filesystem::path& path, const ast::InputLimits& limits,
                                          ReadResult& failure);
    MappedFile(MappedFile&& other) noexcept;
    MappedFile& operator=(MappedFile&&) = delete;
    MappedFile(const MappedFile&) = delete;
    ~MappedFile();

    std::string_view text() const { return mapped_ ? std::string_view(mapped_, size_) : std::string_view(copy_); }
    // Drops the whole pages inside [begin, end) from this process's memory.
    void release(std::size_t begin, std::size_t end) const;
    // What the decoder said about the file and it still read (notes, warnings).
    const ast::DecodedInput& input() const { return input_; }

private:
    MappedFile() = default;
    // The decoder's reading of the mapped bytes, their pages dropped behind it.
    ast::DecodedInput scan(const ast::InputLimits& limits) const;
    const char* mapped_ = nullptr;
    std::size_t size_ = 0;
    std::string copy_;
    ast::DecodedInput input_;   // encoding and problems; its text is empty (the text is above)
};

}  // namespace kerf::project
