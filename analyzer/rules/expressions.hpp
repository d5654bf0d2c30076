// The expressions of a block, as the macro rules and the argument analysis read them (internal to
// analyzer/: rules/macro.cpp, arguments.cpp).
#pragma once

#include "ast/typed.hpp"

namespace kerf::analyzer::rules {

// Calls `f(expr index, in_arithmetic)` for every node under `root`.
template <class F>
void walk(const ast::SyntaxTree& tree, std::int32_t root, bool arithmetic, F&& f) {
    if (root < 0) return;
    const ast::Expr& e = tree.exprs[static_cast<std::size_t>(root)];
    f(root, arithmetic);
    switch (e.kind) {
        case ast::ExprKind::binary: {
            const ast::BinaryOp op = e.binary_op();
            const bool arith = op == ast::BinaryOp::add || op == ast::BinaryOp::sub || op == ast::BinaryOp::mul ||
                               op == ast::BinaryOp::div || op == ast::BinaryOp::mod;
            walk(tree, e.a, arith, f);
            walk(tree, e.b, arith, f);
            break;
        }
        case ast::ExprKind::variable: walk(tree, e.a, false, f); break;   // #[...]: an index, not a value
        case ast::ExprKind::number: break;
        default:
            walk(tree, e.a, arithmetic, f);
            walk(tree, e.b, arithmetic, f);
    }
}

// The expressions a block reads (statement values and conditions, word values) and the constant
// variable numbers it assigns, in execution order.
template <class Read, class Assign>
void block_expressions(const ast::SyntaxTree& tree, const ast::BlockView& view, Read&& read, Assign&& assign) {
    auto statement = [&](const ast::Statement& st, auto& self) -> void {
        read(st.value);
        read(st.label);
        if (st.kind == ast::StatementKind::assign) {
            read(tree.exprs[static_cast<std::size_t>(st.target)].a);   // the index of #[...]
            assign(st.target);
        }
        if (st.then_statement >= 0) self(tree.statements[static_cast<std::size_t>(st.then_statement)], self);
    };
    for (const ast::Token& t : view.tokens()) {
        if (t.kind == ast::TokenKind::statement) statement(tree.statements[static_cast<std::size_t>(t.payload)], statement);
        else if (t.kind == ast::TokenKind::word && t.has(ast::token_flags::value_expr)) read(t.payload);
    }
}

}  // namespace kerf::analyzer::rules
