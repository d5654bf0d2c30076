// An open document: one immutable version of its text, parsed, bound and indexed by line. Features
// and the analysis worker hold a version through a shared pointer and never lock; an edit makes a
// new version from the old one, re-parsing only the lines it touches (reparse.hpp).
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analyzer/incremental.hpp"
#include "ast/source.hpp"
#include "ast/syntax.hpp"
#include "ast/typed.hpp"
#include "lsp/settings.hpp"

namespace kerf::lsp {

// A change of didChange, its range already in UTF-16 positions; no range: the whole text.
struct ContentChange {
    std::optional<std::pair<ast::Position, ast::Position>> range;
    std::string text;
};

class Document {
public:
    // Parses `text` whole. A text kerf cannot read as a program (binary) is kept but not parsed:
    // `refused()` says why and the tree is that of an empty file.
    static std::shared_ptr<const Document> open(std::string uri, std::filesystem::path path, std::int64_t version,
                                                std::string text, std::shared_ptr<const FileSettings> settings);

    // The next version: the changes applied in order. A change whose range is outside the text is
    // skipped and said in `problems`.
    std::shared_ptr<const Document> edit(std::int64_t version, const std::vector<ContentChange>& changes,
                                         std::vector<std::string>& problems) const;
    // The same as edit(), but when `doc` is the only reference to its version the version itself is
    // edited (no copy of a million-line tree per keystroke); otherwise a copy is made as by edit().
    static std::shared_ptr<const Document> edit(std::shared_ptr<const Document> doc, std::int64_t version,
                                                const std::vector<ContentChange>& changes, std::vector<std::string>& problems);
    // The same text under other settings (a new dialect: parsed again whole).
    std::shared_ptr<const Document> with_settings(std::shared_ptr<const FileSettings> settings) const;

    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;

    const std::string& uri() const { return uri_; }
    const std::filesystem::path& path() const { return path_; }
    std::int64_t version() const { return version_; }
    const std::string& text() const { return refused_.empty() ? tree_.text : text_; }
    const ast::SyntaxTree& tree() const { return tree_; }
    const ast::TypedFile& typed() const { return *typed_; }
    const ast::LineIndex& lines() const { return *lines_; }
    const FileSettings& settings() const { return *settings_; }
    const std::shared_ptr<const FileSettings>& settings_ptr() const { return settings_; }
    const dialects::Dialect& dialect() const { return *settings_->dialect; }
    const std::string& refused() const { return refused_; }
    // Blocks parsed by the last edit (whole-file parses count every block): for tests and logs.
    std::uint32_t reparsed_blocks() const { return reparsed_blocks_; }
    // How many edits made this version (each change of a didChange counts; open counts none), and
    // the edits after the first `serial` of them, as incremental checking takes them
    // (analyzer/incremental.hpp); nullopt when they are no longer all kept.
    std::uint64_t serial() const { return serial_; }
    std::optional<std::vector<analyzer::BlockEdit>> edits_since(std::uint64_t serial) const;

    // Byte offset of a UTF-16 position: a column past the line's end means its end, before the
    // line break (LSP 3.17 Position); a line past the last means the end of the text.
    std::uint32_t offset(ast::Position p) const;
    ast::Position position(std::uint32_t offset) const { return lines_->utf16(offset); }
    // The block that holds byte `offset` (the last block for the end of the text).
    std::uint32_t block_at(std::uint32_t offset) const;
    // The token of the block at `offset` that holds it (or ends at it), if any.
    std::optional<std::uint32_t> token_at(std::uint32_t offset) const;

private:
    Document() = default;
    void parse_whole();
    // A new version with this one's identity and edit log, nothing parsed yet.
    std::shared_ptr<Document> successor(std::int64_t version) const;
    // The bytes a ranged change replaces, or nullopt (said in `problems`) when it is outside the text.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> bytes_of(const ContentChange& change, std::size_t index, std::int64_t version,
                                                                    std::vector<std::string>& problems) const;
    // What incremental checking needs to know of the blocks an edit replaced (analyzer/incremental.hpp).
    struct Replaced {
        std::uint64_t facts = 0;
        std::vector<std::int64_t> labels;
    };
    static Replaced replaced(const ast::SyntaxTree& tree, std::uint32_t first, std::uint32_t end);
    // Logs an edit; `old` is nullopt when what it replaced is not known.
    void record(const ast::BlockSplice& splice, std::optional<Replaced> old);
    void record_whole();
    // Applies one ranged change to this version in place; false when it is outside the text.
    bool change_in_place(const ContentChange& change, std::size_t index, std::vector<std::string>& problems);
    std::string uri_;
    std::filesystem::path path_;
    std::int64_t version_ = 0;
    std::shared_ptr<const FileSettings> settings_;
    std::string text_;                      // a refused document's text (otherwise the tree holds it)
    ast::SyntaxTree tree_;
    std::unique_ptr<ast::TypedFile> typed_;
    std::unique_ptr<ast::LineIndex> lines_;
    std::string refused_;
    std::uint32_t reparsed_blocks_ = 0;
    std::uint64_t serial_ = 0;
    std::deque<analyzer::BlockEdit> log_;   // the last edits, the newest last
};

// Why kerf does not read `text` as a program ("" when it does): a binary file (NUL bytes).
std::string refusal(std::string_view text);

}  // namespace kerf::lsp
