// Macro B rules read from the expressions (dialects.md §3.7; interpreter/macro/evaluate.hpp).
#include <bitset>

#include "analyzer/arguments.hpp"
#include "analyzer/rules/common.hpp"
#include "analyzer/rules/expressions.hpp"
#include "dialects/alarms.hpp"

namespace kerf::analyzer::rules {

namespace {

using S = Severity;
namespace fn = dialects::functions;

// #1–#33 read in arithmetic before anything assigned them, in a main program (one that ends
// with M30/M02: it has no arguments). Vacant in arithmetic is 0: a silent wrong value.
class VacantLocal : public StaticCheck {
public:
    void begin_program(const FileContext&, std::size_t, Reporter&) override {
        assigned_.reset();
        known_ = false;
        main_ = false;
    }
    void block(const BlockContext& b, Reporter& out) override {
        if (!has_expressions(b)) return;
        // What the program is (a main program, its arguments) is asked at its first expression:
        // CAM output has none, and the question walks the whole program (bench/RESULTS.md).
        if (!known_) learn_program(b.file, b.program);
        if (!main_) return;
        const ast::SyntaxTree& tree = b.tree();
        auto read = [&](std::int32_t root) {
            walk(tree, root, false, [&](std::int32_t i, bool arithmetic) {
                const ast::Expr& e = tree.exprs[static_cast<std::size_t>(i)];
                if (e.kind != ast::ExprKind::variable || !arithmetic) return;
                const auto n = constant_of(tree, e.a);
                if (!n || *n < 1 || *n > 33 || assigned_[static_cast<std::size_t>(*n)] || arguments_[static_cast<std::size_t>(*n)]) return;
                out.report(e.range(), fmt::format("#{} is read in arithmetic but nothing set it: vacant counts as 0", *n),
                           fmt::format("assign #{} first, or use a common variable #100 and up", *n));
            });
        };
        auto assign = [&](std::int32_t target) {
            if (const auto n = constant_of(tree, tree.exprs[static_cast<std::size_t>(target)].a); n && *n >= 1 && *n <= 33)
                assigned_.set(static_cast<std::size_t>(*n));
        };
        block_expressions(b.tree(), b.view, read, assign);
    }

    void state(StateKey& key) const override {
        key.add(static_cast<std::int64_t>(assigned_.to_ullong() * 4 + main_ * 2 + known_));
        key.add(static_cast<std::int64_t>(arguments_.to_ullong()));
    }

private:
    static bool has_expressions(const BlockContext& b) {
        for (const ast::Token& t : b.view.tokens())
            if (t.kind == ast::TokenKind::statement || (t.kind == ast::TokenKind::word && t.has(ast::token_flags::value_expr)))
                return true;
        return false;
    }
    // A main program ends with M30/M02 (it has no arguments); G65 arguments (callers, or the
    // header's `G65 P9994 A B C`) are set when the macro runs.
    // The M30/M02 is searched from the end (where it stands), and the arguments (a walk of the
    // program and of the file's callers) are asked only of a main program: nothing else reads them.
    void learn_program(const FileContext& file, std::size_t program) {
        known_ = true;
        const ast::Program& p = file.typed.programs()[program];
        main_ = false;
        for (std::uint32_t b = p.end_block; b > p.first_block && !main_; --b) {
            const ast::BlockView v = file.typed.block(b - 1);
            main_ = v.has_code('M', fn::program_end) || v.has_code('M', fn::program_end_rewind);
        }
        arguments_ = main_ ? program_arguments(file.typed, program, file.caller_arguments).locals : LocalSet{};
    }

    std::bitset<34> assigned_;
    LocalSet arguments_;
    bool known_ = false;
    bool main_ = false;
};

class DivisionByZero : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        const ast::SyntaxTree& tree = b.tree();
        auto read = [&](std::int32_t root) {
            walk(tree, root, false, [&](std::int32_t i, bool) {
                const ast::Expr& e = tree.exprs[static_cast<std::size_t>(i)];
                if (e.kind != ast::ExprKind::binary) return;
                if (e.binary_op() != ast::BinaryOp::div && e.binary_op() != ast::BinaryOp::mod) return;
                if (const auto v = constant_of(tree, e.b); v && *v == 0)
                    out.report(e.range(), fmt::format("division by zero ({})", b.file.dialect.alarms.name_of(alarms::macro_division_by_zero)),
                               "check the divisor");
            });
        };
        block_expressions(b.tree(), b.view, read, [](std::int32_t) {});
    }
};

class WriteReadOnly : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        const ast::SyntaxTree& tree = b.tree();
        block_expressions(b.tree(), b.view, [](std::int32_t) {}, [&](std::int32_t target) {
            const ast::Expr& e = tree.exprs[static_cast<std::size_t>(target)];
            if (const auto n = constant_of(tree, e.a); n && *n == 0)
                out.report(e.range(),
                               fmt::format("#0 is always vacant and cannot be written ({})",
                                           b.file.dialect.alarms.name_of(alarms::macro_write_protected)),
                               "assign another variable");
        });
    }
};

}  // namespace

void add_macro(Registry& r) {
    const auto rule = rule_maker(Category::macro);
    r.add(static_rule<VacantLocal>(rule("K4001", "vacant-local-in-arithmetic", S::warning,
        {"A local variable #1–#33 read in arithmetic in a main program before anything assigned it (not a G65 argument: "
         "one its callers pass, or its header documents as `G65 P9994 A B C`).",
         "A vacant variable counts as 0 in arithmetic: the move or the count is silently wrong.",
         "#2=#1+10.\nG01 X#2", "#1=5.\n#2=#1+10.\nG01 X#2", "dialects.md §3.7; [FANUC] vacant variables"})));
    r.add(with_alarms(static_rule<DivisionByZero>(rule("K4002", "division-by-zero", S::error,
        {"A division (or MOD) by zero, written or found when the program runs.", "The control stops with alarm 112.",
         "#1=10/0", "#1=10/2", "interpreter/macro/evaluate.hpp M0112"})), {{alarms::macro_division_by_zero, alarms::macro_division_by_zero}}));
    r.add(with_alarms(static_rule<WriteReadOnly>(rule("K4003", "write-read-only-variable", S::error,
        {"An assignment to #0 or, found by the dry run, to a read-only system variable.",
         "The control stops with alarm 116.", "#0=1", "#100=1", "interpreter/macro/evaluate.hpp M0116"})), {{alarms::macro_write_protected, alarms::macro_write_protected}}));
}

}  // namespace kerf::analyzer::rules
