// The one seam between the server and the project layer (issue 13's `project/`: the .kerf.toml
// model, dialect and machine resolution, the program index). Until that layer is on main this
// file's implementation reads what `kerf check` and `kerf fmt` read (.kerf.toml walking up from the
// file: dialect, machine, dialect_files, [format], [check]) and keeps a small program index of the
// workspace; when it lands, only project_seam.cpp changes (NOTICES.md). Nothing else in lsp/
// resolves settings or finds programs.
//
// Thread-safe: the analysis worker asks for programs while the message thread updates the index.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ast/typed.hpp"
#include "interpreter/program_set.hpp"
#include "lsp/settings.hpp"

namespace kerf::lsp {

// One numbered program of a file.
struct IndexedProgram {
    std::filesystem::path file;
    std::int64_t number = 0;
    std::uint32_t program_index = 0;   // index into the file's ast::TypedFile::programs()
    std::uint32_t begin = 0;           // byte range of the program in its file
    std::uint32_t end = 0;
    std::string comment;               // its first comment, without ( )
};

class ProjectSeam {
public:
    // Reads a file's text (open documents first, then the disk); nullopt when it cannot.
    using Reader = std::function<std::optional<std::string>(const std::filesystem::path&)>;
    explicit ProjectSeam(Reader reader);

    void set_client(ClientSettings settings);
    ClientSettings client() const;
    // A .kerf.toml, dialect or machine file changed: read them again on next use.
    void forget_configs();
    // Dialect, machine, style and rule settings for `file` whose text is `text`.
    std::shared_ptr<const FileSettings> resolve(const std::filesystem::path& file, std::string_view text);
    // The .kerf.toml that governs `file` (walking up), if any.
    std::optional<std::filesystem::path> config_of(const std::filesystem::path& file) const;

    // The program index: every numbered program of every program file under the roots.
    void index_root(const std::filesystem::path& root);
    void update_file(const std::filesystem::path& file, std::string_view text);
    // An open document's programs (it is parsed already: programs_of reads its tree).
    void set_programs(const std::filesystem::path& file, std::vector<IndexedProgram> programs);
    static std::vector<IndexedProgram> programs_of(const std::filesystem::path& file, const ast::TypedFile& typed);
    void remove_file(const std::filesystem::path& file);
    // Program `number` as a call from `from` reaches it outside `from` itself: the file's own
    // folder first, then the nearest file in path order.
    std::optional<IndexedProgram> find_program(std::int64_t number, const std::filesystem::path& from) const;
    std::vector<IndexedProgram> programs_in(const std::filesystem::path& file) const;
    std::vector<IndexedProgram> all_programs() const;
    std::vector<std::filesystem::path> files() const;
    // For interpreter::ProgramSet::set_loader: O number → (name, text) through the index.
    interpreter::ProgramSet::Loader loader_for(const std::filesystem::path& file) const;
    const Reader& reader() const { return reader_; }

private:
    struct Config;
    std::shared_ptr<const Config> config_for(const std::optional<std::filesystem::path>& file);

    Reader reader_;
    mutable std::mutex mutex_;
    ClientSettings client_;
    std::map<std::filesystem::path, std::shared_ptr<const Config>> configs_;
    std::map<std::filesystem::path, std::vector<IndexedProgram>> index_;
};

// True for the file names the index reads: NC extensions (.nc .ngc .tap .cnc .mpf .eia .txt, any
// case) and names without extension that look like an O number (O1234).
bool is_program_file(const std::filesystem::path& path);

}  // namespace kerf::lsp
