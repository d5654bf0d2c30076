#include "formatter/renumber.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "ast/diagnostic_ids.hpp"
#include "dialects/functions.hpp"

namespace kerf::formatter {

namespace {

namespace fn = dialects::functions;
using ast::Diagnostic;
using ast::Severity;

// One reference to a sequence number: a word whose value is the number, or a GOTO label.
struct Reference {
    std::uint32_t block = 0;
    std::uint32_t token = 0;              // the word, or the statement token
    std::optional<ast::Range> label;      // GOTO: the label expression inside the statement
    std::int64_t value = 0;
    std::vector<std::uint32_t> programs;  // the programs whose labels it may mean
};

// What one program's N words become.
struct ProgramNumbers {
    std::map<std::int64_t, std::int64_t> renamed;   // old N (first block with it) → new N
    std::set<std::int64_t> created;                 // every new N of the program
};

class Planner {
public:
    Planner(const ast::TypedFile& file, const Style& style) : file_(file), tree_(file.tree()), style_(style) {}

    std::variant<Renumbering, std::vector<Diagnostic>> run() {
        if (!syntax_clean()) return problems_;
        for (std::uint32_t p = 0; p < file_.programs().size(); ++p) collect_references(p);
        if (!problems_.empty()) return problems_;
        std::vector<std::set<std::int64_t>> referenced(file_.programs().size());
        for (const Reference& r : references_)
            for (const std::uint32_t p : r.programs) referenced[p].insert(r.value);
        std::vector<ProgramNumbers> numbers(file_.programs().size());
        for (std::uint32_t p = 0; p < file_.programs().size(); ++p) numbers[p] = number_program(p, referenced[p]);
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
        std::string_view s = tree_.slice({tokens.front().begin, tokens.back().begin + tokens.back().length});
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
            const auto words = file_.block(b).words_with_role(ast::Role::sequence);
            if (words.size() > 1) {
                refuse(b, tree_.tokens[words[1]].range(), "the block has a second N word",
                       "a block has one N word, at its start; remove the second one (or make it the address it was meant to be)");
                return false;
            }
        }
        return true;
    }

    std::optional<std::uint32_t> program_numbered(std::int64_t number) const {
        const auto& programs = file_.programs();
        for (std::uint32_t p = 0; p < programs.size(); ++p)
            if (programs[p].number == number) return p;
        return std::nullopt;
    }

    bool calls(std::uint32_t caller, std::int64_t number) const {
        const ast::Program& p = file_.programs()[caller];
        for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
            const ast::BlockView view = file_.block(b);
            if (const auto call = view.subprogram_call(); call && call->program == number) return true;
            if (const auto call = view.macro_call(); call && call->program == number) return true;
        }
        return false;
    }

    // M99 P n returns to label n of the caller (dialects.md §3.6): the programs of this file that call
    // this one, and this one itself when it is the file's first program (M99 in a main program).
    std::vector<std::uint32_t> callers_of(std::uint32_t program) const {
        std::vector<std::uint32_t> out;
        const auto number = file_.programs()[program].number;
        for (std::uint32_t p = 0; p < file_.programs().size(); ++p)
            if ((p == 0 && program == 0) || (number && calls(p, *number))) out.push_back(p);
        return out;
    }

    // A numeric word of the block as a reference; refuses an expression.
    void word_reference(std::uint32_t block, std::uint32_t token, std::vector<std::uint32_t> programs,
                        std::string_view what) {
        const ast::Token& t = tree_.tokens[token];
        const auto value = ast::integer_value(tree_, t);
        if (!value) {
            refuse(block, t.range(), fmt::format("{} '{}' is not a plain sequence number", what, tree_.spelling(t)),
                   "write the sequence number as a plain integer, or keep the block numbers (block_numbers = \"keep\")");
            return;
        }
        references_.push_back({block, token, std::nullopt, *value, std::move(programs)});
    }

    void collect_references(std::uint32_t program) {
        const ast::Program& p = file_.programs()[program];
        for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
            const ast::BlockView view = file_.block(b);
            for (const std::uint32_t s : view.statements()) statement_references(b, s, program);
            cycle_references(view, program);
            call_references(view, program);
        }
    }

    void cycle_references(const ast::BlockView& view, std::uint32_t program) {
        for (const ast::CodeRef& g : view.g_codes()) {
            // Cycles whose P and Q name the first and last block of a profile (cycles.md §1–§4: G70–G73 in
            // system A, G72–G75 in C): a trait of the function, never the number.
            if (!g.info || !g.info->has(dialects::traits::profile_cycle))
                continue;
            for (const char letter : {'P', 'Q'})
                if (const auto w = view.word(letter))
                    word_reference(static_cast<std::uint32_t>(view.index()), *w, {program},
                                   fmt::format("{} {}", g.info->spelling, letter));
            return;
        }
    }

    void call_references(const ast::BlockView& view, std::uint32_t program) {
        const auto b = static_cast<std::uint32_t>(view.index());
        if (view.has_code('M', fn::subprogram_call)) {
            if (const auto q = view.word('Q')) {
                // M98 Q: a label of the called program, or of this one without P.
                const auto call = view.subprogram_call();
                const auto target = call ? program_numbered(call->program) : std::optional<std::uint32_t>(program);
                std::vector<std::uint32_t> programs;
                if (target) programs.push_back(*target);   // a program in another file keeps its numbers
                word_reference(b, *q, std::move(programs), "M98 Q");
            }
        }
        if (view.has_code('M', fn::subprogram_return))
            if (const auto p = view.word('P')) word_reference(b, *p, callers_of(program), "M99 P");
    }

    void statement_references(std::uint32_t block, std::uint32_t token, std::uint32_t program) {
        for (std::int32_t s = tree_.tokens[token].payload; s >= 0;) {
            const ast::Statement& st = tree_.statements[static_cast<std::size_t>(s)];
            if (st.kind == ast::StatementKind::goto_ || st.kind == ast::StatementKind::if_goto) label_reference(block, token, st, program);
            s = st.kind == ast::StatementKind::if_then ? st.then_statement : -1;
        }
    }

    void label_reference(std::uint32_t block, std::uint32_t token, const ast::Statement& st, std::uint32_t program) {
        const ast::Expr* e = st.label >= 0 ? &tree_.exprs[static_cast<std::size_t>(st.label)] : nullptr;
        const double v = e && e->kind == ast::ExprKind::number ? tree_.number_value(*e) : NAN;
        if (!std::isfinite(v) || v != std::floor(v) || v < 0 || v > 1e15) {
            const ast::Range r = e ? e->range() : st.range;
            refuse(block, r, fmt::format("GOTO '{}' is computed, so the block it jumps to is known only at run time", tree_.slice(r)),
                   "write the label as a number (GOTO 100), or keep the block numbers (block_numbers = \"keep\")");
            return;
        }
        references_.push_back({block, token, e->range(), static_cast<std::int64_t>(v), {program}});
    }

    // --- numbering ---------------------------------------------------------------------------------

    // The N the interpreter would find for a label: the first block of the program with it.
    ProgramNumbers number_program(std::uint32_t program, const std::set<std::int64_t>& referenced) {
        ProgramNumbers out;
        const ast::Program& p = file_.programs()[program];
        std::set<std::int64_t> seen;
        std::int64_t next = style_.number_start;
        for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
            if (tree_.blocks[b].kind != ast::BlockKind::code) continue;
            const ast::BlockView view = file_.block(b);
            const auto n = view.sequence_number();
            const std::optional<std::int64_t> old =
                n && *n == std::floor(*n) ? std::optional<std::int64_t>(static_cast<std::int64_t>(*n)) : std::nullopt;
            const bool first_of_label = old && seen.insert(*old).second;
            const bool target = first_of_label && referenced.count(*old);
            switch (style_.block_numbers) {
                case BlockNumbers::keep: break;
                case BlockNumbers::remove:
                    if (view.has_sequence_word() && !target) plan_.blocks[b] = Renumbering::kRemove;
                    break;
                case BlockNumbers::renumber:
                case BlockNumbers::referenced:
                    if (style_.block_numbers == BlockNumbers::referenced && !target) {
                        if (view.has_sequence_word()) plan_.blocks[b] = Renumbering::kRemove;
                        break;
                    }
                    if (next > kMaxSequenceNumber) {
                        refuse(b, view.range(), fmt::format("the new number N{} is over N{}", next, kMaxSequenceNumber),
                               "use a smaller number_start or number_step");
                        return out;
                    }
                    plan_.blocks[b] = next;
                    out.created.insert(next);
                    if (first_of_label) out.renamed.emplace(*old, next);
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
        for (const std::uint32_t p : r.programs) {
            const auto it = numbers[p].renamed.find(r.value);
            const std::optional<std::int64_t> mapped = it != numbers[p].renamed.end() ? std::optional(it->second) : std::nullopt;
            if (!mapped && numbers[p].created.count(r.value)) {
                refuse(r.block, tree_.tokens[r.token].range(),
                       fmt::format("it refers to N{}, which no block has, and renumbering would create N{}", r.value, r.value),
                       "fix the reference, or pick number_start/number_step that avoid it");
                return;
            }
            if (mapped && value && *value != *mapped) {
                refuse(r.block, tree_.tokens[r.token].range(),
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

std::variant<Renumbering, std::vector<ast::Diagnostic>> plan_renumbering(const ast::TypedFile& file, const Style& style) {
    if (style.block_numbers == BlockNumbers::keep) return Renumbering{};
    return Planner(file, style).run();
}

}  // namespace kerf::formatter
