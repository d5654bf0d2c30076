#include "references/references.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dialects/functions.hpp"

namespace kerf::references {

namespace {

namespace fn = dialects::functions;
using ast::Token;
using ast::TokenKind;

// Cycles whose P and Q name the first and last block of a profile (cycles.md §1–§5: G70–G73 in
// system A, G72–G75 in system C): a trait of the function (dialects/functions.hpp).
bool profile_cycle(const dialects::CodeInfo& c) { return c.has(dialects::traits::profile_cycle); }

bool macro_code(const dialects::CodeInfo& c) { return c.function == fn::macro_call || c.function == fn::modal_macro_call; }

// A block can hold a reference only with a statement or a P/Q word: most CAM blocks are skipped
// without looking their codes up.
bool may_refer(std::span<const Token> tokens) {
    for (const Token& t : tokens)
        if (t.kind == TokenKind::statement || (t.kind == TokenKind::word && (t.letter == 'P' || t.letter == 'Q')))
            return true;
    return false;
}

std::optional<std::int64_t> plain_number(const ast::SyntaxTree& tree, const Token& t) {
    const auto v = ast::integer_value(tree, t);
    if (!v || *v < 0) return std::nullopt;
    return v;
}

// A GOTO label: a number, or a bracket around one (GOTO [100]: `range` becomes the number's);
// anything else is computed (`range` stays the whole label expression).
std::optional<std::int64_t> constant_label(const ast::SyntaxTree& tree, std::int32_t expr, ast::Range& range) {
    if (expr < 0) return std::nullopt;
    range = tree.exprs[static_cast<std::size_t>(expr)].range();
    while (expr >= 0 && tree.exprs[static_cast<std::size_t>(expr)].kind == ast::ExprKind::bracket)
        expr = tree.exprs[static_cast<std::size_t>(expr)].a;
    if (expr < 0) return std::nullopt;
    const ast::Expr& e = tree.exprs[static_cast<std::size_t>(expr)];
    if (e.kind != ast::ExprKind::number) return std::nullopt;
    const double v = tree.number_value(e);
    if (!std::isfinite(v) || v != std::floor(v) || v < 0 || v > 1e15) return std::nullopt;
    range = e.range();
    return static_cast<std::int64_t>(v);
}

class BlockScan {
public:
    BlockScan(const ast::TypedFile& file, std::uint32_t program, std::uint32_t block, std::vector<Reference>& out)
        : file_(file), tree_(file.tree()), view_(file.block(block)), program_(program), block_(block), out_(out) {}

    void run() {
        const std::size_t first = out_.size();
        for (const std::uint32_t s : view_.statements()) statement(s);
        std::vector<ast::CodeRef> g, m;
        view_.collect_codes(g, m);
        for (const ast::CodeRef& c : g)
            if (c.info && profile_cycle(*c.info)) {
                word(Kind::profile_label, c, 'P');
                word(Kind::profile_label, c, 'Q');
            } else if (c.info && macro_code(*c.info)) {
                word(Kind::macro, c, 'P');
            }
        for (const ast::CodeRef& c : m) {
            if (!c.info) continue;
            if (c.info->function == fn::subprogram_call) subprogram(c);
            else if (c.info->function == fn::subprogram_return) word(Kind::return_label, c, 'P');
            else if (c.info->function == fn::local_subprogram_call) word(Kind::local_call_label, c, 'P');
        }
        std::sort(out_.begin() + static_cast<std::ptrdiff_t>(first), out_.end(),
                  [](const Reference& a, const Reference& b) { return a.token < b.token; });
    }

private:
    Reference base(Kind kind, std::uint32_t token) const {
        Reference r;
        r.kind = kind;
        r.block = block_;
        r.program = program_;
        r.token = token;
        return r;
    }

    // The first `letter` word of the block as the reference of code `c`.
    std::optional<Reference> word_reference(Kind kind, const ast::CodeRef& c, char letter) const {
        const auto w = view_.word(letter);
        if (!w) return std::nullopt;
        const Token& t = tree_.tokens[*w];
        Reference r = base(kind, *w);
        r.code_token = static_cast<std::int32_t>(c.token);
        r.letter = letter;
        r.range = tree_.value_range(t);
        r.value = plain_number(tree_, t);
        return r;
    }

    void word(Kind kind, const ast::CodeRef& c, char letter) {
        if (auto r = word_reference(kind, c, letter)) out_.push_back(std::move(*r));
    }

    // M98 P (packed or P/L, as the dialect reads it: ast::BlockView::subprogram_call) and M98 Q.
    void subprogram(const ast::CodeRef& c) {
        const auto call = view_.subprogram_call();
        if (auto p = word_reference(Kind::subprogram, c, 'P')) {
            if (call) {
                const dialects::SubprogramCall form = file_.dialect().lexical.subprogram_call;
                p->value = call->program;
                p->repeats = call->packed ? call->repeats : 0;
                // P is read packed when the dialect says so, or in the "both" form without L
                // (dialects.md §3.6): then it holds four digits of program, whatever it holds now.
                p->packed = call->packed || form == dialects::SubprogramCall::packed ||
                            (form == dialects::SubprogramCall::both && !view_.word('L'));
            } else {
                p->value.reset();   // P#1, or not an integer: computed
            }
            out_.push_back(std::move(*p));
        }
        if (auto q = word_reference(Kind::call_label, c, 'Q')) {
            if (view_.word('P')) q->label_program = call ? std::optional<std::int64_t>(call->program) : std::nullopt;
            // M98 P#1 Q10: the program is computed, so is the label's program.
            if (view_.word('P') && !call) q->value.reset();
            out_.push_back(std::move(*q));
        }
    }

    void statement(std::uint32_t token) {
        for (std::int32_t s = tree_.tokens[token].payload; s >= 0;) {
            const ast::Statement& st = tree_.statements[static_cast<std::size_t>(s)];
            if (st.kind == ast::StatementKind::goto_ || st.kind == ast::StatementKind::if_goto) {
                Reference r = base(Kind::goto_label, token);
                r.range = st.range;
                r.value = constant_label(tree_, st.label, r.range);
                out_.push_back(std::move(r));
            }
            s = st.kind == ast::StatementKind::if_then ? st.then_statement : -1;
        }
    }

    const ast::TypedFile& file_;
    const ast::SyntaxTree& tree_;
    const ast::BlockView view_;
    std::uint32_t program_, block_;
    std::vector<Reference>& out_;
};

bool calls(const ast::TypedFile& file, std::uint32_t caller, std::int64_t number) {
    const ast::Program& p = file.programs()[caller];
    std::vector<Reference> refs;
    for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
        if (!may_refer(file.tree().block_tokens(b))) continue;
        refs.clear();
        BlockScan(file, caller, b, refs).run();
        for (const Reference& r : refs)
            if (!is_label(r.kind) && r.value == number) return true;
    }
    return false;
}

// Digits as written when the spelling is a plain integer with leading zeros ("0012": 4), else 0.
std::size_t zero_padded_width(std::string_view spelling) {
    if (spelling.size() < 2 || spelling.front() != '0') return 0;
    if (!std::all_of(spelling.begin(), spelling.end(), [](char ch) { return ch >= '0' && ch <= '9'; })) return 0;
    return spelling.size();
}

}  // namespace

const char* to_string(Kind k) {
    switch (k) {
        case Kind::goto_label: return "goto-label";
        case Kind::profile_label: return "profile-label";
        case Kind::call_label: return "call-label";
        case Kind::return_label: return "return-label";
        case Kind::local_call_label: return "local-call-label";
        case Kind::subprogram: return "subprogram";
        case Kind::macro: return "macro";
    }
    return "?";
}

std::vector<Reference> block_references(const ast::TypedFile& file, std::uint32_t program, std::uint32_t block) {
    std::vector<Reference> out;
    if (may_refer(file.tree().block_tokens(block))) BlockScan(file, program, block, out).run();
    return out;
}

std::vector<Reference> file_references(const ast::TypedFile& file) {
    std::vector<Reference> out;
    const auto& programs = file.programs();
    for (std::uint32_t p = 0; p < programs.size(); ++p)
        for (std::uint32_t b = programs[p].first_block; b < programs[p].end_block; ++b)
            if (may_refer(file.tree().block_tokens(b))) BlockScan(file, p, b, out).run();
    return out;
}

std::optional<std::uint32_t> program_of_block(const ast::TypedFile& file, std::uint32_t block) {
    const auto& programs = file.programs();
    const auto it = std::upper_bound(programs.begin(), programs.end(), block,
                                     [](std::uint32_t b, const ast::Program& p) { return b < p.first_block; });
    if (it == programs.begin()) return std::nullopt;
    const auto& p = *std::prev(it);
    if (block >= p.end_block) return std::nullopt;
    return static_cast<std::uint32_t>(std::prev(it) - programs.begin());
}

std::optional<std::uint32_t> program_numbered(const ast::TypedFile& file, std::int64_t number) {
    const auto& programs = file.programs();
    for (std::uint32_t p = 0; p < programs.size(); ++p)
        if (programs[p].number == number) return p;
    return std::nullopt;
}

std::vector<std::uint32_t> label_blocks(const ast::TypedFile& file, std::uint32_t program, std::int64_t label) {
    std::vector<std::uint32_t> out;
    const ast::Program& p = file.programs()[program];
    const double n = static_cast<double>(label);
    for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
        for (const Token& t : file.tree().block_tokens(b)) {
            if (t.kind != TokenKind::word || t.letter != 'N') continue;
            // BlockView::sequence_number: the first N word with a number (what the executor compares).
            if (t.is_number()) {
                if (file.tree().number_value(t) == n) out.push_back(b);
                break;
            }
        }
    }
    return out;
}

std::optional<std::uint32_t> find_label(const ast::TypedFile& file, std::uint32_t program, std::int64_t label) {
    const ast::Program& p = file.programs()[program];
    const double n = static_cast<double>(label);
    for (std::uint32_t b = p.first_block; b < p.end_block; ++b)
        for (const Token& t : file.tree().block_tokens(b))
            if (t.kind == TokenKind::word && t.letter == 'N' && t.is_number()) {
                if (file.tree().number_value(t) == n) return b;
                break;
            }
    return std::nullopt;
}

std::optional<std::uint32_t> find_label_from(const ast::TypedFile& file, std::uint32_t program, std::int64_t label,
                                             std::uint32_t from) {
    if (file.dialect().lexical.label_search != dialects::LabelSearch::forward) return find_label(file, program, label);
    const std::vector<std::uint32_t> blocks = label_blocks(file, program, label);
    const auto after = std::upper_bound(blocks.begin(), blocks.end(), from);
    if (after != blocks.end()) return *after;
    if (!blocks.empty()) return blocks.front();
    return std::nullopt;
}

std::optional<std::uint32_t> jump_target(const ast::TypedFile& file, std::uint32_t program, const Reference& r) {
    if (!r.value) return std::nullopt;
    // A jump inside its own program searches from where it stands; M99 P and M98 P Q name a label
    // of another program, whose search starts at that program's top.
    const bool own = program == r.program && r.kind != Kind::return_label && !r.label_program;
    return own ? find_label_from(file, program, *r.value, r.block) : find_label(file, program, *r.value);
}

std::vector<std::uint32_t> callers_of(const ast::TypedFile& file, std::uint32_t program) {
    std::vector<std::uint32_t> out;
    const auto number = file.programs()[program].number;
    for (std::uint32_t p = 0; p < file.programs().size(); ++p)
        if ((p == 0 && program == 0) || (number && calls(file, p, *number))) out.push_back(p);
    return out;
}

LabelScope label_scope(const ast::TypedFile& file, const Reference& r) {
    LabelScope scope;
    switch (r.kind) {
        case Kind::goto_label:
        case Kind::profile_label:
        case Kind::local_call_label:
            scope.programs.push_back(r.program);
            break;
        case Kind::call_label:
            if (!r.label_program) {
                scope.programs.push_back(r.program);
            } else if (const auto p = program_numbered(file, *r.label_program)) {
                scope.programs.push_back(*p);
            } else {
                scope.other_program = r.label_program;
            }
            break;
        case Kind::return_label:
            scope.programs = callers_of(file, r.program);
            scope.other_callers = true;
            break;
        case Kind::subprogram:
        case Kind::macro:
            break;
    }
    return scope;
}

std::optional<std::string> respell(const ast::SyntaxTree& tree, const Reference& r, std::int64_t number) {
    if (number < 0) return std::nullopt;
    if (r.packed) {
        if (number > 9999) return std::nullopt;   // dialects.md §3.6: the last four digits are the program
        if (r.repeats > 0) return fmt::format("{}{:04}", r.repeats, number);
    }
    const std::size_t width = zero_padded_width(tree.slice(r.range));
    return fmt::format("{:0{}}", number, width);
}

}  // namespace kerf::references
