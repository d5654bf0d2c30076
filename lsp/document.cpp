#include "lsp/document.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "analyzer/incremental.hpp"
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
        tree_ = grammar::parse(std::move(text_), dialect().lexical, grammar::parse_threads());   // two cores for a long file
        text_.clear();
    } else {
        tree_ = grammar::parse(std::string(), dialect().lexical);
    }
    typed_ = std::make_unique<ast::TypedFile>(ast::TypedFile::bind(tree_, dialect(), false, grammar::parse_threads()));
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
    std::shared_ptr<Document> d = successor(version_);
    d->settings_ = std::move(settings);
    d->text_ = text();
    d->parse_whole();
    d->record_whole();   // parsed again whole (the incremental check starts over)
    return d;
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

constexpr std::uint32_t kWholeText = 0xFFFFFFFFu;   // BlockSplice::old_end of a text parsed again whole
constexpr std::size_t kLogLength = 256;              // edits kept for the analysis worker to catch up

}  // namespace

std::uint32_t Document::offset(ast::Position p) const {
    return offset_in(*lines_, text(), p).value_or(static_cast<std::uint32_t>(text().size()));
}

std::optional<std::pair<std::uint32_t, std::uint32_t>> Document::bytes_of(const ContentChange& c, std::size_t index, std::int64_t version,
                                                                          std::vector<std::string>& problems) const {
    const std::string_view text = this->text();
    const auto begin = offset_in(*lines_, text, c.range->first);
    const auto end = offset_in(*lines_, text, c.range->second);
    if (!begin || !end || *begin > *end) {
        problems.push_back(fmt::format("change {} of version {}: range {}:{}-{}:{} is outside the document ({} lines); skipped",
                                       index + 1, version, c.range->first.line, c.range->first.column, c.range->second.line,
                                       c.range->second.column, lines_->line_count()));
        return std::nullopt;
    }
    return std::make_pair(*begin, *end);
}

void Document::record(const ast::BlockSplice& splice, std::optional<Replaced> old) {
    analyzer::BlockEdit e{splice, true, {}};
    if (old && splice.old_end != kWholeText) {
        e.facts_changed = old->facts != analyzer::static_facts(tree_, splice.first, splice.first + splice.added);
        e.labels = std::move(old->labels);
        const std::vector<std::int64_t> added = analyzer::block_labels(tree_, splice.first, splice.first + splice.added);
        e.labels.insert(e.labels.end(), added.begin(), added.end());
    }
    ++serial_;
    log_.push_back(e);
    if (log_.size() > kLogLength) log_.pop_front();
}

void Document::record_whole() { record({0, 0, 0, 0, kWholeText, 0}, std::nullopt); }

Document::Replaced Document::replaced(const ast::SyntaxTree& tree, std::uint32_t first, std::uint32_t end) {
    return {analyzer::static_facts(tree, first, end), analyzer::block_labels(tree, first, end)};
}

std::optional<std::vector<analyzer::BlockEdit>> Document::edits_since(std::uint64_t serial) const {
    if (serial > serial_ || serial_ - serial > log_.size()) return std::nullopt;
    return std::vector<analyzer::BlockEdit>(log_.end() - static_cast<std::ptrdiff_t>(serial_ - serial), log_.end());
}

std::shared_ptr<Document> Document::successor(std::int64_t version) const {
    std::shared_ptr<Document> next(new Document());
    next->uri_ = uri_;
    next->path_ = path_;
    next->version_ = version;
    next->settings_ = settings_;
    next->serial_ = serial_;
    next->log_ = log_;
    return next;
}

std::shared_ptr<const Document> Document::edit(std::int64_t version, const std::vector<ContentChange>& changes,
                                               std::vector<std::string>& problems) const {
    // Each change applies to the text the previous one left (LSP 3.17 didChange).
    const Document* current = this;
    std::shared_ptr<Document> step;   // the intermediate version of a multi-change edit
    for (std::size_t i = 0; i < changes.size(); ++i) {
        const ContentChange& c = changes[i];
        std::shared_ptr<Document> next = current->successor(version);
        if (!c.range) {
            next->text_ = c.text;
            next->parse_whole();
            next->record_whole();
        } else {
            const auto bytes = current->bytes_of(c, i, version, problems);
            if (!bytes) continue;
            const auto [begin, end] = *bytes;
            const std::string_view text = current->text();
            if (!current->refused_.empty() || !refusal(c.text).empty()) {
                // A binary document is only text: the edit is applied to it, and it is read again
                // whole when it may have become a program.
                next->text_.reserve(text.size() + c.text.size());
                next->text_.append(text.substr(0, begin)).append(c.text).append(text.substr(end));
                next->parse_whole();
                next->record_whole();
            } else {
                ast::BlockSplice splice;
                next->tree_ = reparse(current->tree_, {begin, end, c.text}, current->dialect().lexical, splice);
                next->typed_ = std::make_unique<ast::TypedFile>(
                    splice.old_end == kWholeText ? ast::TypedFile::bind(next->tree_, next->dialect(), false, grammar::parse_threads())
                                                 : ast::TypedFile::bind_edited(next->tree_, *current->typed_, splice));
                next->lines_ = std::make_unique<ast::LineIndex>(*current->lines_);
                next->lines_->edit(next->tree_.text, begin, end, static_cast<std::uint32_t>(begin + c.text.size()));
                next->reparsed_blocks_ = splice.added;
                next->record(splice, replaced(current->tree_, splice.first, splice.first + splice.removed));
            }
        }
        step = std::move(next);
        current = step.get();
    }
    if (!step) {   // nothing applied: the same text under the new version
        std::shared_ptr<Document> same = successor(version);
        same->text_ = text();
        same->parse_whole();
        same->serial_ = serial_;   // the same text: no edit
        return same;
    }
    return step;
}

bool Document::change_in_place(const ContentChange& c, std::size_t index, std::vector<std::string>& problems) {
    const auto bytes = bytes_of(c, index, version_, problems);
    if (!bytes) return false;
    ast::BlockSplice splice;
    std::optional<Replaced> old;
    reparse_in_place(tree_, {bytes->first, bytes->second, c.text}, dialect().lexical, splice,
                     [&](const ast::SyntaxTree& tree, std::uint32_t first, std::uint32_t end) { old = replaced(tree, first, end); });
    auto typed = std::make_unique<ast::TypedFile>(splice.old_end == kWholeText ? ast::TypedFile::bind(tree_, dialect(), false, grammar::parse_threads())
                                                                                : ast::TypedFile::bind_edited(tree_, *typed_, splice));
    typed_ = std::move(typed);
    lines_->edit(tree_.text, bytes->first, bytes->second, static_cast<std::uint32_t>(bytes->first + c.text.size()));
    reparsed_blocks_ = splice.added;
    record(splice, std::move(old));
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
        const ast::Range r = tree_.range(tree_.tokens[t]);
        if (r.contains(offset)) return t;
        if (r.end == offset) touching = t;   // the cursor right after a word ("G71|")
    }
    return touching;
}

}  // namespace kerf::lsp
