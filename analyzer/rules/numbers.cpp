// Number and word-form rules read from the tokens of each block.
#include <cmath>
#include <optional>

#include "analyzer/rules/common.hpp"
#include "dialects/functions.hpp"

namespace kerf::analyzer::rules {

namespace {

using S = Severity;

bool is_axis(const ast::Token& t) {
    return t.role() == ast::Role::axis_absolute || t.role() == ast::Role::axis_incremental;
}

// The unit the block's words are read in: the block's own G20/G21 (C: G70/G71), else the modal one.
bool inch_block(const BlockContext& b) {
    std::optional<bool> own;
    for (const ast::CodeRef& c : b.g)
        if (c.info && (c.info->function == dialects::functions::inch_input || c.info->function == dialects::functions::metric_input))
            own = c.info->has(dialects::traits::inch);
    return own ? *own : b.modal.has_trait(dialects::traits::inch);
}

// X10 where an integer is least increments (dialects.md §2 Numbers): 0.010 mm, not 10 mm; under
// G20 0.0010 in (IS-B 0.0001 in); on a rotary axis 0.010°.
class MissingDecimalPoint : public StaticCheck {
    static constexpr double kDeliberateIncrements = 10000;

public:
    void block(const BlockContext& b, Reporter& out) override {
        if (b.file.setup.calculator_decimal) return;
        const bool arc = circular_motion(b);
        const auto tokens = b.view.tokens();
        for (std::uint32_t i = 0; i < tokens.size(); ++i) {
            const ast::Token& t = tokens[i];
            if (t.kind != ast::TokenKind::word || !t.is_number() || t.has(ast::token_flags::has_point)) continue;
            // I J K R are the arc's only when no other code of the block takes them (G28 K F, seed 004).
            const bool arc_word = arc && t.role() == ast::Role::parameter && std::string_view("IJKR").find(t.letter) != std::string_view::npos &&
                                  !code_parameter(b, t.letter, [](const dialects::CodeInfo& c) { return c.has(dialects::traits::motion_group); });
            if (!is_axis(t) && !arc_word) continue;
            const double value = b.tree().number_value(t);
            if (value == 0) continue;   // X0 is zero either way
            // Five digits and more are increments on purpose: nobody forgets the point of a 10 m
            // move (ALL-PROG's C_RUN "G91 G01 C360000": one turn in 0.001° increments).
            if (std::fabs(value) >= kDeliberateIncrements) continue;
            const std::string_view spelling = b.tree().spelling(t);
            const char axis = t.role() == ast::Role::axis_incremental ? b.file.dialect.lexical.incremental_axis_of(t.letter) : t.letter;
            const bool rotary = axis == 'A' || axis == 'B' || axis == 'C' ? b.file.setup.rotary[static_cast<std::size_t>(3 + axis - 'A')] : false;
            const bool inch = !rotary && inch_block(b);
            const char* unit = rotary ? "°" : inch ? " in" : " mm";
            const double increment = rotary ? b.file.setup.increment_deg() : b.file.setup.increment(inch);
            out.report(b.tree().range(t),
                       fmt::format("'{}' has no decimal point: the control reads {} increments = {:g}{}, not {:g}{}",
                                   spelling, value, value * increment, unit, value, unit),
                       fmt::format("write '{}.' if {:g}{} is meant", spelling, value, unit))
                .notes.push_back("the machine reads integers as least input increments (calculator-type input off)");
        }
    }
};

bool takes_arguments(const BlockContext& b) {
    for (const ast::CodeRef& c : b.g)
        if (c.info && c.info->has(dialects::traits::takes_arguments)) return true;
    return false;
}

// Two F words (or two X words ...) in one block: the control takes the last one, or alarms.
class DuplicateAddress : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (takes_arguments(b)) return;   // G65 argument specification II repeats I J K on purpose
        const auto tokens = b.view.tokens();
        std::array<int, 26> first;
        first.fill(-1);
        for (std::uint32_t i = 0; i < tokens.size(); ++i) {
            const ast::Token& t = tokens[i];
            if (t.kind != ast::TokenKind::word || t.letter < 'A' || t.letter > 'Z') continue;
            if (t.letter == 'G' || t.letter == 'M' || t.letter == 'N' || t.letter == 'O') continue;
            int& seen = first[static_cast<std::size_t>(t.letter - 'A')];
            if (seen < 0) {
                seen = static_cast<int>(i);
                continue;
            }
            report(b, tokens[static_cast<std::size_t>(seen)], t, out);
        }
    }

private:
    static void report(const BlockContext& b, const ast::Token& a, const ast::Token& t, Reporter& out) {
        Finding& f = out.report(b.tree().range(t),
                                fmt::format("'{}' repeats address {} of '{}' in the same block", b.tree().spelling(t), t.letter,
                                            b.tree().spelling(a)),
                                "keep one of the two words");
        f.related.push_back({b.tree().range(a), fmt::format("the first {} word", t.letter)});
        if (!a.is_number() || !t.is_number() || b.tree().number_value(a) != b.tree().number_value(t)) return;
        // Same value twice: dropping the second word (and the blanks before it) changes nothing.
        std::uint32_t begin = t.begin;
        while (begin > b.tree().end(a) && (b.tree().text[begin - 1] == ' ' || b.tree().text[begin - 1] == '\t')) --begin;
        f.fix = Fix{"remove the repeated word", {{{begin, b.tree().end(t)}, ""}}};
    }
};

// M08. T0101. N10.: a decimal point on an address that takes whole numbers.
// An M code the dialect's table does not list may be a macro call by M code ([FANUC] custom macro
// call using an M code, parameters 6080–6089: `M165 P9814 D1.415` on the Doosan O1000): the
// block's other words are its arguments, whatever their letters usually address (issue 15).
bool unlisted_m_code(const BlockContext& b) {
    return std::any_of(b.m.begin(), b.m.end(), [](const ast::CodeRef& c) { return !c.info && c.key; });
}

class PointOnInteger : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (takes_arguments(b) || unlisted_m_code(b)) return;   // macro arguments: any letter, any value
        for (const ast::Token& t : b.view.tokens()) {
            if (t.kind != ast::TokenKind::word || !t.is_number() || !t.has(ast::token_flags::has_point)) continue;
            const std::string_view spelling = b.tree().spelling(t);
            // A cycle's data word may have a point (G384 H20.0 D300. M20.: depth, speed, brake;
            // gcode-tables.md §1 SPINNER rows), and H may be the incremental C axis (dialects.md §3.9).
            const bool integer_address = std::string_view("MTNOLHD").find(t.letter) != std::string_view::npos &&
                                         t.role() != ast::Role::axis_incremental && !code_parameter(b, t.letter);
            if (!(integer_address || (t.letter == 'G' && spelling.ends_with('.')))) continue;
            Finding& f = out.report(b.tree().range(t), fmt::format("'{}': address {} takes a whole number", spelling, t.letter),
                                    "remove the decimal point");
            if (spelling.ends_with('.'))
                f.fix = Fix{"remove the decimal point", {{{b.tree().end(t) - 1, b.tree().end(t)}, ""}}};
        }
    }
};

class ByteOrderMark : public StaticCheck {
public:
    void begin_program(const FileContext& file, std::size_t program, Reporter& out) override {
        if (program != 0 || file.tree().tokens.empty()) return;
        const ast::Token& t = file.tree().tokens[0];
        if (t.kind != ast::TokenKind::bom) return;
        out.report(file.tree().range(t), "the file starts with a UTF-8 byte order mark", "save the file without BOM")
            .fix = Fix{"remove the byte order mark", {{file.tree().range(t), ""}}};
    }
    void block(const BlockContext&, Reporter&) override {}
};

// Tokens of a kind in every block (comments are often in comment-only blocks, which the static
// pass skips, so these rules walk the tree themselves once per file).
template <class F>
void for_each_comment(const FileContext& file, std::size_t program, F&& f) {
    const ast::Program& p = file.typed.programs()[program];
    const ast::SyntaxTree& tree = file.tree();
    const std::uint32_t end = p.end_block < tree.block_count() ? tree.block_first_token(p.end_block)
                                                               : static_cast<std::uint32_t>(tree.tokens.size());
    for (std::uint32_t i = tree.block_first_token(p.first_block); i < end; ++i)
        if (tree.tokens[i].kind == ast::TokenKind::comment) f(tree.tokens[i]);
}

class EmptyComment : public StaticCheck {
public:
    void begin_program(const FileContext& file, std::size_t program, Reporter& out) override {
        for_each_comment(file, program, [&](const ast::Token& t) {
            std::string_view s = file.tree().spelling(t);
            if (s.find_first_not_of("() \t") != std::string_view::npos) return;
            out.report(file.tree().range(t), "empty comment", "remove it").fix = Fix{"remove the empty comment", {{file.tree().range(t), ""}}};
        });
    }
    void block(const BlockContext&, Reporter&) override {}
};

class NonAsciiComment : public StaticCheck {
public:
    void begin_program(const FileContext& file, std::size_t program, Reporter& out) override {
        for_each_comment(file, program, [&](const ast::Token& t) {
            const std::string_view s = file.tree().spelling(t);
            for (const char c : s)
                if (static_cast<unsigned char>(c) >= 0x80) {
                    out.report(file.tree().range(t), "comment with characters outside ASCII",
                               "write comments in ASCII for controls that read ISO/EIA tape code");
                    return;
                }
        });
    }
    void block(const BlockContext&, Reporter&) override {}
};

// Lower-case addresses, one finding per file (the p2g generator writes every axis letter in lower
// case: one finding says it, not 64) at the first; its fix upper-cases them all. Lower-case words
// are among the facts incremental checking digests (analyzer/incremental.cpp), so the file-wide
// count and fix stay true after an edit.
class LowerCase : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (reported_) return;
        for (const ast::Token& t : b.view.tokens()) {
            if (t.kind != ast::TokenKind::word || !t.has(ast::token_flags::lower_case)) continue;
            reported_ = true;
            std::vector<TextEdit> edits;
            for (std::uint32_t i = 0; i < b.tree().block_count(); ++i)
                for (const ast::Token& u : b.tree().block_tokens(i))
                    if (u.kind == ast::TokenKind::word && u.has(ast::token_flags::lower_case))
                        edits.push_back({{u.begin, u.begin + 1}, std::string(1, u.letter)});
            const ast::Range first{t.begin, t.begin + 1};
            const std::string_view letter = b.tree().slice(first);
            Finding& f = out.report(first,
                                    edits.size() == 1 ? fmt::format("lower-case address '{}'", letter)
                                                      : fmt::format("{} lower-case addresses in this file, the first '{}'", edits.size(), letter),
                                    "write the addresses in upper case");
            f.fix = Fix{"upper-case the address letters", std::move(edits)};
            return;
        }
    }
    void state(StateKey& key) const override { key.add(reported_); }

private:
    bool reported_ = false;
};

}  // namespace

void add_numbers(Registry& r) {
    const auto rule = rule_maker(Category::syntax);
    r.add(static_rule<MissingDecimalPoint>(rule("K1020", "missing-decimal-point", S::warning,
        {"An axis or arc value without decimal point on a machine that reads integers as least increments.",
         "X10 moves to 0.010 mm, not 10 mm: the tool goes somewhere else than the drawing says.",
         "G01 X10 Y10 F100.", "G01 X10. Y10. F100.", "dialects.md §2 Numbers; cycles.md §0"})));
    r.add(fixable(static_rule<DuplicateAddress>(rule("K1021", "duplicate-address", S::warning,
        {"The same address twice in one block (two F words).",
         "The control takes one of them or raises alarm 'address duplicated'; the other value is lost.",
         "G01 X10. F0.010 F.010", "G01 X10. F0.010", "corpus Steady_rest_maker.nc; [FANUC]"}))));
    r.add(fixable(static_rule<PointOnInteger>(rule("K1022", "point-on-integer-address", S::warning,
        {"A decimal point on an address that takes whole numbers (M08., T0101., N10.).",
         "Many controls raise a format alarm for a point on M, T, N or O.",
         "M08.", "M08", "dialects.md §2 Numbers; corpus 1003.NC"}))));
    r.add(fixable(static_rule<ByteOrderMark>(rule("K1023", "byte-order-mark", S::info,
        {"The file starts with a UTF-8 byte order mark.",
         "A control reading the file over RS-232 or from a card sees three unknown bytes before '%' or 'O'.",
         "<BOM>O0001", "O0001", "corpus O0001.txt, O0005.nc"}))));
    r.add(fixable(opt_in(static_rule<EmptyComment>(rule("K1024", "empty-comment", S::hint,
        {"An empty comment '()'.", "Harmless on the control; noise for the reader (style, off by default).",
         "N01 G00 X0. ()", "N01 G00 X0.", "corpus O3380"})))));
    r.add(opt_in(static_rule<NonAsciiComment>(rule("K1025", "non-ascii-comment", S::info,
        {"A comment with bytes outside ASCII (Cyrillic, a Latin-1 degree sign).",
         "ISO/EIA tape code has no such characters: some controls reject the block or show garbage (opt-in).",
         "(ТОКАРНЫЙ 90°)", "(TOKARNYJ 90 DEG)", "dialects.md §2 Characters"}))));
    r.add(fixable(static_rule<LowerCase>(rule("K1026", "lower-case-address", S::info,
        {"Address letters in lower case (one finding per file).", "FANUC ISO code has upper-case addresses; some controls reject lower case.",
         "g01 z-18.5", "G01 Z-18.5", "dialects.md §2; corpus p2g"}))));
}

}  // namespace kerf::analyzer::rules
