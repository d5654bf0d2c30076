// The server's face of the project layer (issue 13's `project/`): one project::Workspace whose
// files are the open documents over the disk, so the .kerf.toml model, dialect and machine
// resolution (the client's kerf.dialect / kerf.machine as the workspace's overrides) and the
// program index are exactly those of `kerf check` and `kerf fmt`. This file turns the workspace's
// answers into what the features use (FileSettings per document, IndexedProgram with its file);
// nothing else in lsp/ resolves settings or finds programs.
//
// Thread-safe: the analysis worker asks for programs while the message thread updates the index.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ast/typed.hpp"
#include "interpreter/program_set.hpp"
#include "lsp/settings.hpp"
#include "project/workspace.hpp"

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
    // At most the first `max_bytes` of the text of an open document (nullopt when `path` is not
    // open): open documents hide their files on disk for every read of the workspace
    // (configuration, index, subprograms). A head is all the recognition of a file reads: a
    // million-line document is not copied for it.
    using Reader = std::function<std::optional<std::string>(const std::filesystem::path&, std::size_t max_bytes)>;
    explicit ProjectSeam(Reader open_documents);

    void set_client(ClientSettings settings);
    ClientSettings client() const;
    // A .kerf.toml, dialect or machine file changed: read them again on next use.
    void forget_configs();
    // Goes up whenever the settings or the programs of the workspace may answer differently
    // (new numbers in a file, a file on disk changed or gone, configuration): the analysis then
    // checks open documents whole again (analyzer/incremental.hpp `world`). An open document's
    // edits that keep its program numbers leave it as it is.
    std::uint64_t generation() const { return generation_.load(); }
    // Dialect, machine, style and rule settings for `file` whose text is `text`.
    std::shared_ptr<const FileSettings> resolve(const std::filesystem::path& file, std::string_view text);
    // The .kerf.toml that governs `file` (walking up), if any.
    std::optional<std::filesystem::path> config_of(const std::filesystem::path& file) const;

    // The program index: every numbered program of every program file under the roots.
    void index_root(const std::filesystem::path& root);
    void update_file(const std::filesystem::path& file, std::string_view text);
    // An open document's programs (it is parsed already: programs_of reads its tree); true when
    // its program numbers changed (calls from other documents may reach others now).
    bool set_programs(const std::filesystem::path& file, std::vector<IndexedProgram> programs);
    static std::vector<IndexedProgram> programs_of(const std::filesystem::path& file, const ast::TypedFile& typed);
    void remove_file(const std::filesystem::path& file);
    // Program `number` as a call from `from` reaches it outside `from` itself (project/index.hpp:
    // the file's folder, then the nearest folder, within its folder and [programs] library); when
    // no such file holds it and `anywhere`, the nearest file of the whole index (go to definition
    // still finds it; the analysis asks without `anywhere`, as `kerf check` does).
    std::optional<IndexedProgram> find_program(std::int64_t number, const std::filesystem::path& from, bool anywhere = true);
    // The other files a call from `from` reaches that hold `number`, first the one the dry run
    // takes (analyzer K3010), named as `kerf check` names them.
    std::vector<std::string> program_files(std::int64_t number, const std::filesystem::path& from);
    std::vector<IndexedProgram> programs_in(const std::filesystem::path& file) const;
    std::vector<IndexedProgram> all_programs() const;
    std::vector<std::filesystem::path> files() const;
    // For interpreter::ProgramSet::set_loader: O number → (name, text) through the index.
    interpreter::ProgramSet::Loader loader_for(const std::filesystem::path& file);
    // A file's text: the open document, else the disk.
    std::optional<std::string> read(const std::filesystem::path& file) const;

private:
    std::shared_ptr<const project::FileSystem> files_;
    mutable project::Workspace workspace_;
    mutable std::mutex mutex_;
    ClientSettings client_;
    std::atomic<std::uint64_t> generation_{0};
};

// True for the file names the index reads: NC extensions (.nc .ngc .tap .cnc .mpf .eia .txt, any
// case) and names without extension that look like an O number (O1234).
bool is_program_file(const std::filesystem::path& path);

}  // namespace kerf::lsp
