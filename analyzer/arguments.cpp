#include "analyzer/arguments.hpp"

#include <cctype>
#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "analyzer/rules/common.hpp"
#include "analyzer/rules/expressions.hpp"
#include "dialects/functions.hpp"
#include "interpreter/macro/arguments.hpp"

namespace kerf::analyzer {

namespace {

// "( G65 P9994 A B C )" → the locals of A, B, C when P names `number`; the letters may carry values
// ("A1." "B#2"): each word's first character counts. Stops at the first word that is no letter.
LocalSet arguments_in_comment(std::string_view text, std::int64_t number) {
    LocalSet out;
    std::string upper(text);
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    std::size_t at = upper.find("G65");
    while (at != std::string::npos) {
        std::size_t i = at + 3;
        while (i < upper.size() && upper[i] == ' ') ++i;
        if (i < upper.size() && upper[i] == 'P') {
            std::size_t j = i + 1;
            std::int64_t p = 0;
            while (j < upper.size() && std::isdigit(static_cast<unsigned char>(upper[j]))) p = p * 10 + (upper[j++] - '0');
            if (j > i + 1 && p == number) {
                interpreter::macro::ArgumentMapper mapper;
                while (j < upper.size()) {
                    while (j < upper.size() && upper[j] == ' ') ++j;
                    if (j >= upper.size() || !std::isalpha(static_cast<unsigned char>(upper[j]))) break;
                    if (const int local = mapper.variable(upper[j]); local > 0 && local <= 33) out.set(static_cast<std::size_t>(local));
                    while (j < upper.size() && upper[j] != ' ' && upper[j] != ')') ++j;
                }
                return out;
            }
        }
        at = upper.find("G65", at + 3);
    }
    return out;
}

}  // namespace

LocalSet documented_arguments(const ast::TypedFile& file, std::size_t program) {
    const ast::Program& p = file.programs()[program];
    if (!p.number) return {};
    const ast::SyntaxTree& tree = file.tree();
    LocalSet out;
    for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
        bool words = false;
        for (const ast::Token& t : tree.block_tokens(b)) {
            if (t.kind == ast::TokenKind::comment) out |= arguments_in_comment(tree.spelling(t), *p.number);
            words |= t.kind == ast::TokenKind::statement ||
                     (t.kind == ast::TokenKind::word && t.letter != 'O' && t.letter != 'N');
        }
        if (words) break;   // the header ends at the first word of the program
    }
    return out;
}

LocalSet file_caller_arguments(const ast::TypedFile& file, std::int64_t number, bool& called) {
    LocalSet out;
    called = false;
    const ast::SyntaxTree& tree = file.tree();
    for (std::uint32_t b = 0; b < tree.block_count(); ++b) {
        const ast::BlockView view = file.block(b);
        // The P word first: looking up a block's codes costs more, and most blocks have no P.
        const auto p = view.word('P');
        if (!p || ast::integer_value(tree, tree.tokens[*p]) != number) continue;
        const auto call = view.macro_call();
        if (!call || call->program != number) continue;
        called = true;
        interpreter::macro::ArgumentMapper mapper;
        for (const std::uint32_t ti : call->arguments)
            if (const int local = mapper.variable(tree.tokens[ti].letter); local > 0 && local <= 33)
                out.set(static_cast<std::size_t>(local));
    }
    return out;
}

namespace {

// Calls `first_read(n)` for each variable number in [lo, hi] that the program reads before anything
// in it assigns it (text order, constant numbers only).
void reads_before_assigned(const ast::TypedFile& file, std::size_t program, double lo, double hi,
                           const std::function<void(int)>& first_read) {
    const ast::Program& p = file.programs()[program];
    const ast::SyntaxTree& tree = file.tree();
    if (tree.exprs.empty()) return;   // no expression, no variable (most CAM output): no walk of its blocks
    std::set<int> assigned;
    const auto number = [&](std::int32_t name) -> std::optional<int> {
        const auto n = rules::constant_of(tree, name);
        if (!n || *n < lo || *n > hi || *n != std::floor(*n)) return std::nullopt;
        return static_cast<int>(*n);
    };
    for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
        const ast::BlockView view = file.block(b);
        const auto read = [&](std::int32_t root) {
            rules::walk(tree, root, false, [&](std::int32_t i, bool) {
                const ast::Expr& e = tree.exprs[static_cast<std::size_t>(i)];
                if (e.kind != ast::ExprKind::variable) return;
                if (const auto n = number(e.a); n && !assigned.count(*n)) first_read(*n);
            });
        };
        const auto assign = [&](std::int32_t target) {
            if (const auto n = number(tree.exprs[static_cast<std::size_t>(target)].a)) assigned.insert(*n);
        };
        rules::block_expressions(tree, view, read, assign);
    }
}

}  // namespace

LocalSet argument_reads(const ast::TypedFile& file, std::size_t program) {
    LocalSet read_first;
    reads_before_assigned(file, program, 1, 33, [&](int n) { read_first.set(static_cast<std::size_t>(n)); });
    return read_first;
}

bool reads_common_inputs(const ast::TypedFile& file, std::size_t program) {
    bool found = false;
    const auto seen = [&](int) { found = true; };
    reads_before_assigned(file, program, 100, 199, seen);
    reads_before_assigned(file, program, 500, 999, seen);
    return found;
}

LocalSet vacancy_tested(const ast::TypedFile& file, std::size_t program) {
    const ast::Program& p = file.programs()[program];
    const ast::SyntaxTree& tree = file.tree();
    LocalSet out;
    if (tree.exprs.empty()) return out;   // no expression, no test of a variable
    const auto local_of = [&](std::int32_t e) -> std::optional<int> {
        if (e < 0 || tree.exprs[static_cast<std::size_t>(e)].kind != ast::ExprKind::variable) return std::nullopt;
        const auto n = rules::constant_of(tree, tree.exprs[static_cast<std::size_t>(e)].a);
        // #0 (vacant) and the locals #1–#33 are all this asks about; #6e94 must not reach the cast (UBSan).
        if (!n || !(*n >= 0 && *n < 34)) return std::nullopt;
        return static_cast<int>(*n);
    };
    for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
        const auto read = [&](std::int32_t root) {
            rules::walk(tree, root, false, [&](std::int32_t i, bool) {
                const ast::Expr& e = tree.exprs[static_cast<std::size_t>(i)];
                if (e.kind != ast::ExprKind::binary) return;
                if (e.binary_op() != ast::BinaryOp::eq && e.binary_op() != ast::BinaryOp::ne) return;
                const auto a = local_of(e.a), c = local_of(e.b);
                if (a == 0 && c && *c >= 1 && *c <= 33) out.set(static_cast<std::size_t>(*c));
                if (c == 0 && a && *a >= 1 && *a <= 33) out.set(static_cast<std::size_t>(*a));
            });
        };
        rules::block_expressions(tree, file.block(b), read, [](std::int32_t) {});
    }
    return out;
}

ProgramArguments program_arguments(const ast::TypedFile& file, std::size_t program,
                                   const std::function<std::vector<int>(std::int64_t)>& index_callers) {
    ProgramArguments out;
    out.locals = documented_arguments(file, program);
    out.documented = out.locals.any();
    out.locals |= vacancy_tested(file, program);
    const auto number = file.programs()[program].number;
    if (!number) return out;
    bool called = false;
    out.locals |= file_caller_arguments(file, *number, called);
    out.caller_known = called;
    if (index_callers) {
        const std::vector<int> locals = index_callers(*number);
        out.caller_known |= !locals.empty();
        for (const int l : locals)
            if (l >= 1 && l <= 33) out.locals.set(static_cast<std::size_t>(l));
    }
    return out;
}

}  // namespace kerf::analyzer
