#include "formatter/renumber.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "ast/diagnostic_ids.hpp"
#include "dialects/functions.hpp"
#include "references/references.hpp"

namespace kerf::formatter {

namespace {

using ast::Diagnostic;
using ast::Severity;

// One reference to a sequence number: a word whose value is the number, or a GOTO label.
struct Reference {
    std::uint32_t block = 0;
    std::uint32_t token = 0;              // the word, or the statement token
    std::optional<ast::Range> label;      // GOTO: the label expression inside the statement
    std::int64_t value = 0;
    // The programs whose labels it may mean, each with the block it lands on there (none: no block
    // carries the label; references::jump_target, which follows the dialect's label search).
    std::vector<std::pair<std::uint32_t, std::optional<std::uint32_t>>> targets;
};

// What one program's N words become.
struct ProgramNumbers {
    std::set<std::int64_t> created;                 // every new N of the program
};

class Planner {
public:
    Planner(const ast::TypedFile& file, const Style& style) : file_(file), tree_(file.tree()), style_(style) {}

    std::variant<Renumbering, std::vector<Diagnostic>> run() {
        if (!syntax_clean()) return problems_;
        collect_references();
        if (!problems_.empty()) return problems_;
        std::set<std::uint32_t> targets;   // the blocks something jumps to
        for (const Reference& r : references_)
            for (const auto& [program, block] : r.targets)
                if (block) targets.insert(*block);
        std::vector<ProgramNumbers> numbers(file_.programs().size());
        for (std::uint32_t p = 0; p < file_.programs().size(); ++p) numbers[p] = number_program(p, targets);
        if (!problems_.empty()) return problems_;
        for (const Reference& r : references_) resolve(r, numbers);
        if (!problems_.empty()) return problems_;
        return std::move(plan_);
    }

private:
    const ast::TypedFile& file_;
    const ast::SyntaxTree& tree_;
    const Style& style_;
    std::vector<Reference> references_;
    std::vector<Diagnostic> problems_;
    Renumbering plan_;

    // The block's text for messages: "N40 GOTO #1" (at most 60 bytes).
    std::string quote(std::uint32_t block) const {
        const auto tokens = tree_.block_tokens(block);
        if (tokens.empty()) return {};
        std::string_view s = tree_.slice({tokens.front().begin, tree_.end(tokens.back())});
        return std::string(s.substr(0, 60)) + (s.size() > 60 ? "..." : "");
    }

    void refuse(std::uint32_t block, ast::Range range, std::string message, std::string hint) {
        problems_.push_back({range, Severity::error, ast::diagnostic_id::renumber_refused,
                             fmt::format("cannot renumber: {} in block '{}'", message, quote(block)), std::move(hint)});
    }

    // A block that does not parse may hold a reference kerf cannot see; a second N word would
    // become the block's label once the first is renumbered or removed (S0302).
    bool syntax_clean() {
        for (std::uint32_t b = 0; b < tree_.block_count(); ++b) {
            if (tree_.blocks[b].has(ast::block_flags::has_error)) {
                refuse(b, tree_.block_range(b), "the block has a syntax error and may hold a reference",
                       "fix the syntax errors first (kerf parse lists them)");
                return false;
            }
            if (has_inner_program_word(tree_, tree_.block_tokens(b))) {
                refuse(b, tree_.block_range(b), "the block has an O word after its first word, which reprinting could make a program start",
                       "put the O word on a line of its own, or remove it");
                return false;
            }
            const auto words = file_.block(b).words_with_role(ast::Role::sequence);
            if (words.size() > 1) {
                refuse(b, tree_.range(tree_.tokens[words[1]]), "the block has a second N word",
                       "a block has one N word, at its start; remove the second one (or make it the address it was meant to be)");
                return false;
            }
        }
        return true;
    }

    // Every label reference of the file (references/references.hpp: GOTO n, G70–G73 P/Q, M98 Q,
    // M99 P, M97 P) with the programs whose labels it may mean; a computed one is refused.
    void collect_references() {
        for (const references::Reference& r : references::file_references(file_)) {
            if (!references::is_label(r.kind)) continue;
            if (!r.value) {
                refuse_computed(r);
                continue;
            }
            if (const auto second = second_word(r)) {
                // Which of two P (or Q) words a code takes is not certain (the control may raise an
                // alarm; kerf's dry run takes the last, its references the first): renumbering one
                // of them could change the jump.
                refuse(r.block, tree_.range(tree_.tokens[*second]),
                       fmt::format("{} is given twice ('{}' and '{}')", what(r), tree_.spelling(tree_.tokens[r.token]),
                                   tree_.spelling(tree_.tokens[*second])),
                       fmt::format("keep one {} word in the block (K1021)", r.letter));
                continue;
            }
            // A label of a program in another file (M98 P Q) keeps its value: that file keeps its numbers.
            const references::LabelScope scope = references::label_scope(file_, r);
            const std::optional<ast::Range> label = r.kind == references::Kind::goto_label ? std::optional(r.range) : std::nullopt;
            Reference ref{r.block, r.token, label, *r.value, {}};
            for (const std::uint32_t p : scope.programs) ref.targets.emplace_back(p, references::jump_target(file_, p, r));
            references_.push_back(std::move(ref));
        }
    }

    // Another word of the reference's letter in its block, if there is one.
    std::optional<std::uint32_t> second_word(const references::Reference& r) const {
        const ast::BlockView view = file_.block(r.block);
        const auto tokens = view.tokens();
        for (std::uint32_t i = 0; i < tokens.size(); ++i) {
            const std::uint32_t index = view.first_token() + i;
            if (index != r.token && tokens[i].kind == ast::TokenKind::word && tokens[i].letter == r.letter) return index;
        }
        return std::nullopt;
    }

    // "G70 P", "M99 P": the code's spelling in the dialect table and the letter.
    std::string what(const references::Reference& r) const {
        std::vector<ast::CodeRef> g, m;
        file_.block(r.block).collect_codes(g, m);
        for (const auto* codes : {&g, &m})
            for (const ast::CodeRef& c : *codes)
                if (static_cast<std::int32_t>(c.token) == r.code_token && c.info) return fmt::format("{} {}", c.info->spelling, r.letter);
        return fmt::format("{} {}", tree_.spelling(tree_.tokens[static_cast<std::size_t>(r.code_token)]), r.letter);
    }

    void refuse_computed(const references::Reference& r) {
        if (r.kind == references::Kind::goto_label) {
            refuse(r.block, r.range, fmt::format("GOTO '{}' is computed, so the block it jumps to is known only at run time", tree_.slice(r.range)),
                   "write the label as a number (GOTO 100), or keep the block numbers (block_numbers = \"keep\")");
            return;
        }
        const ast::Token& t = tree_.tokens[r.token];
        if (r.kind == references::Kind::call_label && ast::integer_value(tree_, t)) {
            refuse(r.block, tree_.range(t), fmt::format("M98 Q '{}' is a label of the program P names, and P is computed", tree_.spelling(t)),
                   "write P as a plain program number, or keep the block numbers (block_numbers = \"keep\")");
            return;
        }
        refuse(r.block, tree_.range(t), fmt::format("{} '{}' is not a plain sequence number", what(r), tree_.spelling(t)),
               "write the sequence number as a plain integer, or keep the block numbers (block_numbers = \"keep\")");
    }

    // The block has an N word, and taking it away leaves no block that starts with '%': such a line
    // is a tape mark and would close the program there (grammar/parse.cpp; fuzz_formatter).
    // And a block that is nothing but its N word stays when it is all its program runs (`n4` before
    // `O00001` on one line is a program of its own): without it the program is gone, and the next
    // one would be the first to run (fuzz_formatter, --verify).
    bool removable_sequence_word(std::uint32_t b, bool program_has_other_code) const {
        const auto tokens = tree_.block_tokens(b);
        bool other_words = false;
        std::optional<bool> removable;
        for (std::size_t i = 0; i < tokens.size(); ++i) {
            const bool word = tokens[i].kind == ast::TokenKind::word || tokens[i].kind == ast::TokenKind::statement;
            if (!word) continue;
            if (removable || tokens[i].role() != ast::Role::sequence) {
                other_words = true;
                continue;
            }
            removable = i + 1 >= tokens.size() || tokens[i + 1].kind != ast::TokenKind::percent;
        }
        return removable.value_or(false) && (other_words || program_has_other_code);
    }

    // A code block of the program with a word or a statement that is not its N (one pass per program:
    // a block of nothing but its N is never that block itself).
    bool runs_code(const ast::Program& p) const {
        for (std::uint32_t o = p.first_block; o < p.end_block; ++o) {
            if (tree_.blocks[o].kind != ast::BlockKind::code) continue;
            for (const ast::Token& t : tree_.block_tokens(o))
                if ((t.kind == ast::TokenKind::word && t.role() != ast::Role::sequence) || t.kind == ast::TokenKind::statement)
                    return true;
        }
        return false;
    }

    // --- numbering ---------------------------------------------------------------------------------

    // New numbers for the blocks of a program; `targets` are the blocks jumps land on (the
    // interpreter's label search: the first from the top, or the next one after the jump).
    ProgramNumbers number_program(std::uint32_t program, const std::set<std::uint32_t>& targets) {
        ProgramNumbers out;
        const ast::Program& p = file_.programs()[program];
        const bool program_code = style_.block_numbers != BlockNumbers::renumber && runs_code(p);
        std::int64_t next = style_.number_start;
        for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
            // An empty file is one code block without tokens (grammar/parse.cpp): no block to number.
            if (tree_.blocks[b].kind != ast::BlockKind::code || tree_.block_first_token(b) == tree_.block_token_end(b)) continue;
            const ast::BlockView view = file_.block(b);
            const bool target = targets.count(b) > 0;
            switch (style_.block_numbers) {
                case BlockNumbers::keep: break;
                case BlockNumbers::remove:
                    if (!target && removable_sequence_word(b, program_code)) plan_.blocks[b] = Renumbering::kRemove;
                    break;
                case BlockNumbers::renumber:
                case BlockNumbers::referenced:
                    if (style_.block_numbers == BlockNumbers::referenced && !target) {
                        if (!view.has_sequence_word()) break;
                        if (removable_sequence_word(b, program_code)) {
                            plan_.blocks[b] = Renumbering::kRemove;
                            break;
                        }
                        // An N that stays (before a '%') is numbered with the others: kept, its old
                        // number could be one this renumbering gives another block (fuzz_formatter).
                    }
                    if (next > kMaxSequenceNumber) {
                        refuse(b, view.range(), fmt::format("the new number N{} is over N{}", next, kMaxSequenceNumber),
                               "use a smaller number_start or number_step");
                        return out;
                    }
                    plan_.blocks[b] = next;
                    out.created.insert(next);
                    next += style_.number_step;
                    break;
            }
        }
        return out;
    }

    // The new value of a reference: the same in every program it may mean, or a refusal. A
    // reference to no block keeps its value, unless renumbering would create that number.
    void resolve(const Reference& r, const std::vector<ProgramNumbers>& numbers) {
        std::optional<std::int64_t> value;
        for (const auto& [p, target] : r.targets) {
            std::optional<std::int64_t> mapped;
            if (target) {
                const auto it = plan_.blocks.find(*target);
                mapped = it != plan_.blocks.end() && it->second != Renumbering::kRemove ? it->second : r.value;
            }
            if (!mapped && numbers[p].created.count(r.value)) {
                refuse(r.block, tree_.range(tree_.tokens[r.token]),
                       fmt::format("it refers to N{}, which no block has, and renumbering would create N{}", r.value, r.value),
                       "fix the reference, or pick number_start/number_step that avoid it");
                return;
            }
            if (mapped && value && *value != *mapped) {
                refuse(r.block, tree_.range(tree_.tokens[r.token]),
                       fmt::format("N{} is in several programs that it may return to, and they are renumbered differently", r.value),
                       "put the subprogram in its own file, or keep the block numbers");
                return;
            }
            if (mapped) value = mapped;
        }
        if (!value || *value == r.value) return;
        if (r.label) plan_.statements[r.token].push_back({*r.label, *value});
        else plan_.words[r.token] = *value;
    }
};

}  // namespace

bool has_inner_program_word(const ast::SyntaxTree& tree, std::span<const ast::Token> tokens) {
    // program_word_after_first without its test that the words before are plain: a percent sign, a
    // statement or an error before the O means no reading ever starts a program there.
    bool words_before = false;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const ast::Token& t = tokens[i];
        if (t.kind == ast::TokenKind::comment || t.kind == ast::TokenKind::bom ||
            (i == 0 && t.kind == ast::TokenKind::block_delete))
            continue;
        if (t.kind != ast::TokenKind::word) return false;
        if (t.letter == 'O') {
            const std::string_view value = tree.value_spelling(t);
            if (!value.empty() && value.front() >= '0' && value.front() <= '9') return words_before;
        }
        words_before = true;
    }
    return false;
}

std::variant<Renumbering, std::vector<ast::Diagnostic>> plan_renumbering(const ast::TypedFile& file, const Style& style) {
    if (style.block_numbers == BlockNumbers::keep) return Renumbering{};
    return Planner(file, style).run();
}

}  // namespace kerf::formatter
