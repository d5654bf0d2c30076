// FANUC Macro B expressions (reference: dialects.md §3.7; FANUC custom macro B):
//   precedence, highest first: functions, brackets and #variables; unary -/+;
//   * / AND MOD; + - OR XOR; EQ NE GT LT GE LE.
// Nodes are built in post-order on the builder's stack (see builder.hpp).
#pragma once

#include <boost/spirit/home/x3.hpp>

#include "grammar/builder.hpp"
#include "grammar/number.hpp"

namespace kerf::grammar {

namespace x3 = boost::spirit::x3;

template <typename Ctx>
Builder& builder_of(Ctx const& ctx) {
    return x3::get<builder_tag>(ctx).get();
}

// Rolls the builder back when its subject fails, so backtracking never leaves half-built nodes.
template <typename Subject>
struct transactional_directive : x3::unary_parser<Subject, transactional_directive<Subject>> {
    using base_type = x3::unary_parser<Subject, transactional_directive<Subject>>;
    static bool const has_attribute = false;
    using attribute_type = x3::unused_type;
    constexpr transactional_directive(Subject const& inner) : base_type(inner) {}

    template <typename It, typename Ctx, typename RCtx, typename Attr>
    bool parse(It& first, It const& last, Ctx const& ctx, RCtx& rctx, Attr&) const {
        Builder& b = builder_of(ctx);
        const Builder::Checkpoint saved = b.save();
        const bool mergeable = b.last_error_mergeable;
        It it = first;
        if (this->subject.parse(it, last, ctx, rctx, x3::unused)) {
            first = it;
            return true;
        }
        b.restore(saved);
        b.last_error_mergeable = mergeable;
        return false;
    }
};

// Bounds the recursion of expressions: every nesting (bracket, function, unary sign) passes through
// the unary rule, which this guards. Past the limit the subject fails and the builder records where,
// so the error rules can say so instead of the stack overflowing (fuzz/regressions/stack-overflow-*).
template <typename Subject>
struct depth_guard_directive : x3::unary_parser<Subject, depth_guard_directive<Subject>> {
    using base_type = x3::unary_parser<Subject, depth_guard_directive<Subject>>;
    static bool const has_attribute = false;
    using attribute_type = x3::unused_type;
    constexpr depth_guard_directive(Subject const& inner) : base_type(inner) {}

    template <typename It, typename Ctx, typename RCtx, typename Attr>
    bool parse(It& first, It const& last, Ctx const& ctx, RCtx& rctx, Attr&) const {
        Builder& b = builder_of(ctx);
        if (b.depth >= Builder::kMaxExpressionDepth) {
            if (!b.too_deep_at) b.too_deep_at = &*first;
            return false;
        }
        ++b.depth;
        const bool ok = this->subject.parse(first, last, ctx, rctx, x3::unused);
        --b.depth;
        return ok;
    }
};

struct depth_guard_gen {
    template <typename Subject>
    constexpr depth_guard_directive<typename x3::extension::as_parser<Subject>::value_type> operator[](
        Subject const& subject) const {
        return {x3::as_parser(subject)};
    }
};
inline constexpr depth_guard_gen depth_guard{};

struct transactional_gen {
    template <typename Subject>
    constexpr transactional_directive<typename x3::extension::as_parser<Subject>::value_type> operator[](
        Subject const& subject) const {
        return {x3::as_parser(subject)};
    }
};
inline constexpr transactional_gen transactional{};

namespace expr_detail {

using ast::BinaryOp;
using ast::Expr;
using ast::ExprKind;
using ast::Function;

auto const blanks = x3::omit[*x3::char_(" \t\r\f\v")];

inline x3::symbols<std::uint8_t> make_symbols(std::initializer_list<std::pair<const char*, BinaryOp>> items) {
    x3::symbols<std::uint8_t> s;
    for (const auto& [name, op] : items) s.add(name, static_cast<std::uint8_t>(op));
    return s;
}

// Keyword operators are case-insensitive (lower-case programs exist); x3::no_case wraps them.
const x3::symbols<std::uint8_t> additive_ops =
    make_symbols({{"+", BinaryOp::add}, {"-", BinaryOp::sub}, {"or", BinaryOp::or_}, {"xor", BinaryOp::xor_}});
const x3::symbols<std::uint8_t> multiplicative_ops =
    make_symbols({{"*", BinaryOp::mul}, {"/", BinaryOp::div}, {"and", BinaryOp::and_}, {"mod", BinaryOp::mod}});
const x3::symbols<std::uint8_t> comparison_ops =
    make_symbols({{"eq", BinaryOp::eq}, {"ne", BinaryOp::ne}, {"gt", BinaryOp::gt}, {"lt", BinaryOp::lt},
                  {"ge", BinaryOp::ge}, {"le", BinaryOp::le}});

inline x3::symbols<std::uint8_t> make_functions() {
    x3::symbols<std::uint8_t> s;
    const std::pair<const char*, Function> items[] = {
        {"sin", Function::sin},   {"cos", Function::cos},   {"tan", Function::tan},   {"asin", Function::asin},
        {"acos", Function::acos}, {"atan", Function::atan}, {"sqrt", Function::sqrt}, {"sqr", Function::sqrt},
        {"abs", Function::abs},   {"bin", Function::bin},   {"bcd", Function::bcd},   {"round", Function::round},
        {"rnd", Function::round}, {"fix", Function::fix},   {"fup", Function::fup},   {"ln", Function::ln},
        {"exp", Function::exp},   {"pow", Function::pow},   {"adp", Function::adp}};
    for (const auto& [name, f] : items) s.add(name, static_cast<std::uint8_t>(f));
    return s;
}
const x3::symbols<std::uint8_t> functions = make_functions();

// --- actions -------------------------------------------------------------------------------------

auto const push_number = [](auto& ctx) {
    Builder& b = builder_of(ctx);
    const NumberLit& n = x3::_attr(ctx);
    Expr e;
    e.kind = ExprKind::number;
    e.begin = b.offset(n.begin);
    e.end = b.offset(n.end);
    e.scale = static_cast<std::uint8_t>(n.scale);
    b.store_number(n, e.a, e.flags);
    b.push_expr(e);
};

template <ExprKind Kind>
struct wrap_one {
    template <typename Ctx>
    void operator()(Ctx& ctx) const {
        Builder& b = builder_of(ctx);
        Expr e;
        e.kind = Kind;
        e.begin = b.offset(&*x3::_attr(ctx).begin());
        e.end = b.offset(&*x3::_attr(ctx).begin() + x3::_attr(ctx).size());
        e.a = b.pop();
        b.push_expr(e);
    }
};

auto const push_operator = [](auto& ctx) { builder_of(ctx).operators.push_back(x3::_attr(ctx)); };

auto const make_binary = [](auto& ctx) {
    Builder& b = builder_of(ctx);
    Expr e;
    e.kind = ExprKind::binary;
    e.op = b.operators.back();
    b.operators.pop_back();
    e.b = b.pop();
    e.a = b.pop();
    e.begin = b.tree.exprs[static_cast<std::size_t>(e.a)].begin;
    e.end = b.tree.exprs[static_cast<std::size_t>(e.b)].end;
    b.push_expr(e);
};

auto const open_function = [](auto& ctx) {
    Builder& b = builder_of(ctx);
    b.functions.push_back({static_cast<Function>(x3::_attr(ctx)), b.stack.size()});
};

auto const close_function = [](auto& ctx) {
    Builder& b = builder_of(ctx);
    const Builder::FunctionMark mark = b.functions.back();
    b.functions.pop_back();
    Expr e;
    e.kind = ExprKind::function;
    e.op = static_cast<std::uint8_t>(mark.function);
    e.begin = b.offset(&*x3::_attr(ctx).begin());
    e.end = b.offset(&*x3::_attr(ctx).begin() + x3::_attr(ctx).size());
    if (b.stack.size() >= mark.depth + 2) e.b = b.pop();
    e.a = b.pop();
    b.push_expr(e);
};

// --- rules ---------------------------------------------------------------------------------------

x3::rule<struct expression_class> const expression = "expression";
x3::rule<struct comparison_class> const comparison = "comparison";
x3::rule<struct additive_class> const additive = "additive";
x3::rule<struct multiplicative_class> const multiplicative = "multiplicative";
x3::rule<struct unary_class> const unary = "unary";
x3::rule<struct primary_class> const primary = "primary";
x3::rule<struct variable_class> const variable = "variable";
x3::rule<struct bracket_class> const bracket = "bracket";
x3::rule<struct function_call_class> const function_call = "function call";

number_parser const expr_number{false, false};

auto const bracket_def = x3::omit[x3::raw[x3::lit('[') >> blanks >> expression >> blanks >> x3::lit(']')][wrap_one<ExprKind::bracket>{}]];

// #1, #[#2+1]; FANUC has no ## (use #[#n]).
auto const variable_def = x3::omit[x3::raw[x3::lit('#') >> blanks >> (expr_number[push_number] | bracket)][wrap_one<ExprKind::variable>{}]];

// SIN[a], ATAN[a,b], POW[a,b]; the classic two-argument form ATAN[a]/[b] is read as a division of
// ATAN[a] by [b] and recognised by the interpreter (see ast/typed.hpp, atan2_operands).
auto const function_call_def =
    transactional[x3::omit[x3::raw[x3::no_case[functions][open_function] >> blanks >> x3::lit('[') >> blanks >> expression >> blanks >>
                   -(x3::lit(',') >> blanks >> expression >> blanks) >> x3::lit(']')][close_function]]];

auto const primary_def = expr_number[push_number] | variable | transactional[bracket] | function_call;

auto const unary_def = depth_guard[x3::omit[x3::raw[x3::lit('-') >> blanks >> unary][wrap_one<ExprKind::negate>{}]] |
                                   x3::omit[x3::raw[x3::lit('+') >> blanks >> unary][wrap_one<ExprKind::plus>{}]] |
                                   primary];

auto const multiplicative_def =
    unary >> *transactional[blanks >> x3::no_case[multiplicative_ops][push_operator] >> blanks >> unary][make_binary];

auto const additive_def =
    multiplicative >> *transactional[blanks >> x3::no_case[additive_ops][push_operator] >> blanks >> multiplicative][make_binary];

auto const comparison_def =
    additive >> *transactional[blanks >> x3::no_case[comparison_ops][push_operator] >> blanks >> additive][make_binary];

auto const expression_def = comparison;

BOOST_SPIRIT_DEFINE(expression, comparison, additive, multiplicative, unary, primary, variable, bracket, function_call)

}  // namespace expr_detail
}  // namespace kerf::grammar
