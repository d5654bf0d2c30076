// The programs an interpreter run can reach. No file I/O here: the CLI (or the language server)
// loads files and hands them over; the resolver only searches what it was given, in the order the
// reference gives: the same file first, then the other files (folder: O1000, O1000.nc, 1000.nc).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ast/source.hpp"
#include "ast/typed.hpp"
#include "interpreter/loaded_file.hpp"

namespace kerf::interpreter {

struct ProgramRef {
    std::uint32_t file = 0;      // index into ProgramSet::files
    std::uint32_t program = 0;   // index into that file's TypedFile::programs()
};

class ProgramSet {
public:
    // Asked for a program the set does not hold (O number → name and text), e.g. by the CLI from
    // the folder of the main file. The interpreter itself never touches files.
    using Loader = std::function<std::optional<std::pair<std::string, std::string>>(std::int64_t number)>;
    void set_loader(Loader loader, const dialects::Dialect* dialect) {
        loader_ = std::move(loader);
        loader_dialect_ = dialect;
    }
    const Loader& loader() const { return loader_; }
    // find(), then the loader; a loaded file joins the set.
    std::optional<ProgramRef> find_or_load(std::int64_t number, std::uint32_t from_file);

    // Parses and binds `text` with the dialect; returns the file index.
    std::uint32_t add(std::string name, std::string text, const dialects::Dialect& dialect);
    // A file parsed and bound by its owner, used in place (loaded_file.hpp).
    std::uint32_t add_parsed(std::string name, std::shared_ptr<const void> owner, const ast::TypedFile& typed,
                             const ast::LineIndex& lines);
    // A file read in pieces as the run reaches them (loaded_file.hpp); `text` must outlive the set.
    std::uint32_t add_stream(std::string name, std::string_view text, const dialects::Dialect& dialect,
                             StreamOptions options);
    const LoadedFile& file(std::uint32_t i) const { return *files_[i]; }
    std::size_t file_count() const { return files_.size(); }
    // O number → program: the calling file first, then every other file in order.
    std::optional<ProgramRef> find(std::int64_t number, std::uint32_t from_file) const;
    // The first program of a file (the main program of `kerf run FILE`).
    std::optional<ProgramRef> first_program(std::uint32_t file) const;

private:
    std::vector<std::unique_ptr<LoadedFile>> files_;
    Loader loader_;
    const dialects::Dialect* loader_dialect_ = nullptr;
};

}  // namespace kerf::interpreter
