#include "lsp/document.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "grammar/parse.hpp"
#include "lsp/reparse.hpp"

namespace kerf::lsp {

std::string refusal(std::string_view text) {
    // A NUL byte never appears in an NC program (reference/dialects.md §1: ISO/EIA text); an
    // image, an archive or a UTF-16 file has them early. One memchr over the text.
    if (std::memchr(text.data(), '\0', text.size()))
        return "the document holds NUL bytes: a binary file (or UTF-16 text), not an NC program; kerf does not analyse it";
    return {};
}

void Document::parse_whole() {
    refused_ = refusal(text_);
    if (refused_.empty()) {
        tree_ = grammar::parse(std::move(text_), dialect().lexical);
        text_.clear();
    } else {
        tree_ = grammar::parse(std::string(), dialect().lexical);
    }
    typed_ = std::make_unique<ast::TypedFile>(ast::TypedFile::bind(tree_, dialect()));
    lines_ = std::make_unique<ast::LineIndex>(text());
    reparsed_blocks_ = static_cast<std::uint32_t>(tree_.block_count());
}

std::shared_ptr<const Document> Document::open(std::string uri, std::filesystem::path path, std::int64_t version,
                                               std::string text, std::shared_ptr<const FileSettings> settings) {
    std::shared_ptr<Document> d(new Document());
    d->uri_ = std::move(uri);
    d->path_ = std::move(path);
    d->version_ = version;
    d->settings_ = std::move(settings);
    d->text_ = std::move(text);
    d->parse_whole();
    return d;
}

std::shared_ptr<const Document> Document::with_settings(std::shared_ptr<const FileSettings> settings) const {
    return open(uri_, path_, version_, text(), std::move(settings));
}

namespace {

// The byte offset of an LSP position: a column past the line's end means its end (LSP 3.17
// "Position": the line terminator is not part of the line); nullopt for a line past the last.
std::optional<std::uint32_t> offset_in(const ast::LineIndex& lines, std::string_view text, ast::Position p) {
    if (p.line >= lines.line_count()) {
        // The position just past a final line break is the start of an empty last line.
        if (p.line == lines.line_count() && p.column == 0 && !text.empty() && text.back() == '\n') return static_cast<std::uint32_t>(text.size());
        return std::nullopt;
    }
    std::uint32_t end = p.line + 1 < lines.line_count() ? lines.line_start(p.line + 1) : static_cast<std::uint32_t>(text.size());
    if (end > lines.line_start(p.line) && text[end - 1] == '\n') --end;
    if (end > lines.line_start(p.line) && text[end - 1] == '\r') --end;
    return std::min(lines.offset_of_utf16(p), end);
}

}  // namespace

std::shared_ptr<const Document> Document::edit(std::int64_t version, const std::vector<ContentChange>& changes,
                                               std::vector<std::string>& problems) const {
    // Each change applies to the text the previous one left (LSP 3.17 didChange).
    const Document* current = this;
    std::shared_ptr<Document> step;   // the intermediate version of a multi-change edit
    for (std::size_t i = 0; i < changes.size(); ++i) {
        const ContentChange& c = changes[i];
        std::shared_ptr<Document> next(new Document());
        next->uri_ = uri_;
        next->path_ = path_;
        next->version_ = version;
        next->settings_ = settings_;
        if (!c.range) {
            next->text_ = c.text;
            next->parse_whole();
        } else {
            const std::string_view text = current->text();
            const auto begin = offset_in(current->lines(), text, c.range->first);
            const auto end = offset_in(current->lines(), text, c.range->second);
            if (!begin || !end || *begin > *end) {
                problems.push_back(fmt::format("change {} of version {}: range {}:{}-{}:{} is outside the document ({} lines); skipped",
                                               i + 1, version, c.range->first.line, c.range->first.column, c.range->second.line,
                                               c.range->second.column, current->lines().line_count()));
                continue;
            }
            std::string edited;
            if (!current->refused_.empty() || !refusal(c.text).empty()) {
                // A binary document is only text: the edit is applied to it, and it is read again
                // whole when it may have become a program.
                edited.reserve(text.size() + c.text.size());
                edited.append(text.substr(0, *begin)).append(c.text).append(text.substr(*end));
                next->text_ = std::move(edited);
                next->parse_whole();
            } else {
                ast::BlockSplice splice;
                next->tree_ = reparse(current->tree_, {*begin, *end, c.text}, current->dialect().lexical, splice);
                next->typed_ = std::make_unique<ast::TypedFile>(
                    splice.old_end == 0xFFFFFFFFu ? ast::TypedFile::bind(next->tree_, next->dialect())
                                                  : ast::TypedFile::bind_edited(next->tree_, *current->typed_, splice));
                next->lines_ = std::make_unique<ast::LineIndex>(next->tree_.text);
                next->reparsed_blocks_ = splice.added;
            }
        }
        step = std::move(next);
        current = step.get();
    }
    if (!step) {   // nothing applied: the same text under the new version
        return open(uri_, path_, version, text(), settings_);
    }
    return step;
}

bool Document::change_in_place(const ContentChange& c, std::size_t index, std::vector<std::string>& problems) {
    const std::string_view text = this->text();
    const auto begin = offset_in(*lines_, text, c.range->first);
    const auto end = offset_in(*lines_, text, c.range->second);
    if (!begin || !end || *begin > *end) {
        problems.push_back(fmt::format("change {} of version {}: range {}:{}-{}:{} is outside the document ({} lines); skipped",
                                       index + 1, version_, c.range->first.line, c.range->first.column, c.range->second.line,
                                       c.range->second.column, lines_->line_count()));
        return false;
    }
    ast::BlockSplice splice;
    reparse_in_place(tree_, {*begin, *end, c.text}, dialect().lexical, splice);
    auto typed = std::make_unique<ast::TypedFile>(splice.old_end == 0xFFFFFFFFu ? ast::TypedFile::bind(tree_, dialect())
                                                                                 : ast::TypedFile::bind_edited(tree_, *typed_, splice));
    typed_ = std::move(typed);
    lines_ = std::make_unique<ast::LineIndex>(tree_.text);
    reparsed_blocks_ = splice.added;
    return true;
}

std::shared_ptr<const Document> Document::edit(std::shared_ptr<const Document> doc, std::int64_t version,
                                               const std::vector<ContentChange>& changes, std::vector<std::string>& problems) {
    bool in_place = doc.use_count() == 1 && doc->refused_.empty();
    for (const ContentChange& c : changes) in_place = in_place && c.range && refusal(c.text).empty();
    if (!in_place) return doc->edit(version, changes, problems);
    // Sole owner: the object was created non-const (open()), and nobody else can see it change.
    auto* self = const_cast<Document*>(doc.get());
    self->version_ = version;
    for (std::size_t i = 0; i < changes.size(); ++i) self->change_in_place(changes[i], i, problems);
    return doc;
}

std::uint32_t Document::block_at(std::uint32_t offset) const {
    const auto& blocks = tree_.blocks;
    const auto it = std::upper_bound(blocks.begin(), blocks.end(), offset,
                                     [](std::uint32_t o, const ast::Block& b) { return o < b.begin; });
    return it == blocks.begin() ? 0 : static_cast<std::uint32_t>(it - blocks.begin() - 1);
}

std::optional<std::uint32_t> Document::token_at(std::uint32_t offset) const {
    if (tree_.block_count() == 0) return std::nullopt;
    const std::uint32_t b = block_at(offset);
    const std::uint32_t first = tree_.block_first_token(b);
    const std::uint32_t end = tree_.block_token_end(b);
    std::optional<std::uint32_t> touching;
    for (std::uint32_t t = first; t < end; ++t) {
        const ast::Range r = tree_.tokens[t].range();
        if (r.contains(offset)) return t;
        if (r.end == offset) touching = t;   // the cursor right after a word ("G71|")
    }
    return touching;
}

}  // namespace kerf::lsp
