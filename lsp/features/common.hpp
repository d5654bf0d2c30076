// What several features share (internal to lsp/features): the reference under the cursor, where a
// label or a program is defined, the call sites of a program across the workspace, ranges of
// blocks and programs, and time/length texts.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lsp/features.hpp"
#include "lsp/protocol.hpp"
#include "references/references.hpp"

namespace kerf::lsp {

// A block's words from its first to its last token (no line break); the block's range when empty.
ast::Range words_range(const ast::SyntaxTree& tree, std::uint32_t block);
// The range of a program: its first block to the end of its last block's words.
ast::Range program_range(const Document& doc, std::uint32_t program);

// The reference whose number the cursor is on (the word, or the GOTO statement's label).
std::optional<references::Reference> reference_at(const Document& doc, std::uint32_t offset);
// The N word the cursor is on: its block.
std::optional<std::uint32_t> label_word_at(const Document& doc, std::uint32_t offset);
// The O word the cursor is on: its program.
std::optional<std::uint32_t> program_word_at(const Document& doc, std::uint32_t offset);
// The first N word of a block (its label), if any.
std::optional<std::uint32_t> n_word(const ast::SyntaxTree& tree, std::uint32_t block);

// A label in one program of one document.
struct LabelTarget {
    std::shared_ptr<const Document> doc;
    std::uint32_t program = 0;
    std::int64_t label = 0;
    std::uint32_t block = 0;   // the block the control jumps to
};
// A program of one document.
struct ProgramTarget {
    std::shared_ptr<const Document> doc;
    std::uint32_t program = 0;
    std::int64_t number = 0;
};

// Where a label reference of `s.doc` lands (several places for an M99 P with several callers).
std::vector<LabelTarget> label_targets(const Snapshot& s, const references::Reference& r);
// The program a call from `from` to O`number` reaches: the same file first, then the index.
std::optional<ProgramTarget> program_target(const Snapshot& s, const std::shared_ptr<const Document>& from, std::int64_t number);

// What the cursor names: a label (on an N word or a label reference) or a program (on an O word or
// a call). A label that no block carries gives nothing.
struct Named {
    std::optional<LabelTarget> label;
    std::optional<ProgramTarget> program;
};
Named named_at(const Snapshot& s, std::uint32_t offset);

// Where a definition is: the N word of the target block, the O word of the program.
json::object label_location(const LabelTarget& t);
json::object program_location(const ProgramTarget& t);
// The range of the number a reference writes: the label of a GOTO, the value of a P/Q word.
inline ast::Range reference_range(const references::Reference& r) { return r.range; }

// A call of a program found in the workspace.
struct CallSite {
    std::shared_ptr<const Document> doc;
    references::Reference ref;
};
// Every call (M98 P, G65/G66 P) in the open documents and indexed files that reaches `target`.
std::vector<CallSite> call_sites(const Snapshot& s, const ProgramTarget& target);
// Every label reference that lands on `target` (this document, and M98 P Q from other files).
std::vector<CallSite> label_references(const Snapshot& s, const LabelTarget& target);

// The edits that turn the document's text into `text`: one TextEdit over the bytes that differ,
// from the start of the first changed line (none when they are equal), so the client keeps the
// cursor and folds elsewhere.
json::array edits_to(const Document& doc, const std::string& text);

// "1:02.5" / "12.3 s" for a duration.
std::string duration(double seconds);
// A number as the reference writes it: "12.5", "-3", "0.001".
std::string number_text(double v);

// The description of a code in the document's language.
std::string description(const dialects::CodeInfo& info, const std::string& language);

}  // namespace kerf::lsp
