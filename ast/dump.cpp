#include "ast/dump.hpp"

#include <fmt/format.h>

#include <boost/json.hpp>

namespace kerf::ast {

namespace json = boost::json;

std::string expr_to_string(const SyntaxTree& tree, std::int32_t index) {
    if (index < 0 || static_cast<std::size_t>(index) >= tree.exprs.size()) return "?";
    const Expr& e = tree.exprs[static_cast<std::size_t>(index)];
    switch (e.kind) {
        case ExprKind::number: return std::string(tree.slice(e.range()));
        // fmt::format, not "literal" + string: GCC 12 warns falsely on the latter (-Wrestrict).
        case ExprKind::variable: return fmt::format("#{}", expr_to_string(tree, e.a));
        case ExprKind::negate: return fmt::format("(- {})", expr_to_string(tree, e.a));
        case ExprKind::plus: return fmt::format("(+ {})", expr_to_string(tree, e.a));
        case ExprKind::bracket: return fmt::format("[{}]", expr_to_string(tree, e.a));
        case ExprKind::binary:
            return fmt::format("({} {} {})", to_string(e.binary_op()), expr_to_string(tree, e.a), expr_to_string(tree, e.b));
        case ExprKind::function:
            return e.b >= 0 ? fmt::format("({} {} {})", to_string(e.function()), expr_to_string(tree, e.a),
                                          expr_to_string(tree, e.b))
                            : fmt::format("({} {})", to_string(e.function()), expr_to_string(tree, e.a));
    }
    return "?";
}

std::string statement_to_string(const SyntaxTree& tree, std::int32_t index) {
    const Statement& s = tree.statements[static_cast<std::size_t>(index)];
    switch (s.kind) {
        case StatementKind::assign:
            return fmt::format("{} = {}", expr_to_string(tree, s.target), expr_to_string(tree, s.value));
        case StatementKind::if_goto:
            return fmt::format("IF {} GOTO {}", expr_to_string(tree, s.value), expr_to_string(tree, s.label));
        case StatementKind::if_then:
            return fmt::format("IF {} THEN {}", expr_to_string(tree, s.value), statement_to_string(tree, s.then_statement));
        case StatementKind::if_words: return fmt::format("IF {} (the block's words)", expr_to_string(tree, s.value));
        case StatementKind::goto_: return "GOTO " + expr_to_string(tree, s.label);
        case StatementKind::while_do:
            return fmt::format("WHILE {} DO {}", expr_to_string(tree, s.value), expr_to_string(tree, s.label));
        case StatementKind::do_: return "DO " + expr_to_string(tree, s.label);
        case StatementKind::end: return "END " + expr_to_string(tree, s.label);
        case StatementKind::dprnt: return fmt::format("DPRNT \"{}\"", tree.slice(s.text));
        case StatementKind::bprnt: return fmt::format("BPRNT \"{}\"", tree.slice(s.text));
        case StatementKind::popen: return "POPEN";
        case StatementKind::pclos: return "PCLOS";
    }
    return "?";
}

namespace {

std::string number_text(double v) {
    if (v == 0) return "0";
    return fmt::format("{}", v);
}

std::string value_text(const SyntaxTree& tree, const Token& t) {
    if (t.has(token_flags::value_none)) return "none";
    if (t.has(token_flags::value_expr)) return expr_to_string(tree, t.payload);
    return number_text(tree.number_value(t));
}

std::string token_text(const TypedFile& file, const Token& t) {
    const SyntaxTree& tree = file.tree();
    const std::string spelled(tree.spelling(t));
    switch (t.kind) {
        case TokenKind::comment: return spelled;
        case TokenKind::eob: return ";";
        case TokenKind::percent: return "%";
        case TokenKind::bom: return "{bom}";
        case TokenKind::block_delete: return spelled + "{block-delete}";
        case TokenKind::error: return fmt::format("{{error {}}}", spelled);
        case TokenKind::statement: return fmt::format("{{{}}}", statement_to_string(tree, t.payload));
        case TokenKind::comma_word: return fmt::format("{}{{comma {}={}}}", spelled, t.letter, value_text(tree, t));
        case TokenKind::word: break;
    }
    const std::string value = value_text(tree, t);
    switch (t.role()) {
        case Role::sequence: return fmt::format("{}{{seq {}}}", spelled, value);
        case Role::program: return fmt::format("{}{{program {}}}", spelled, value);
        case Role::g_code:
        case Role::m_code: {
            const auto key = t.is_number() ? dialects::code_key(tree.number_value(t)) : std::nullopt;
            const dialects::CodeInfo* info = key ? file.dialect().fast_code(t.letter, *key) : nullptr;
            if (!info) return fmt::format("{}{{{} unknown}}", spelled, t.letter == 'G' ? "g" : "m");
            if (t.letter == 'G') return fmt::format("{}{{g {} {}}}", spelled, info->group, info->function);
            return fmt::format("{}{{m {}}}", spelled, info->function);
        }
        case Role::axis_absolute: return fmt::format("{}{{axis {}={}}}", spelled, t.letter, value);
        case Role::axis_incremental:
            return fmt::format("{}{{inc {}+={}}}", spelled, file.dialect().lexical.incremental_axis_of(t.letter), value);
        case Role::direct_drawing: return fmt::format("{}{{drawing {}={}}}", spelled, t.letter, value);
        case Role::parameter: return fmt::format("{}{{{}={}}}", spelled, t.letter, value);
        case Role::none: break;
    }
    return fmt::format("{}{{{}={}}}", spelled, t.letter, value);
}

json::object range_json(Range r, const LineIndex& lines) {
    const Position b = lines.utf8(r.begin);
    const Position e = lines.utf8(r.end);
    const Position b16 = lines.utf16(r.begin);
    const Position e16 = lines.utf16(r.end);
    return {{"begin", r.begin},
            {"end", r.end},
            {"start", {{"line", b.line + 1}, {"column", b.column + 1}, {"utf16_column", b16.column + 1}}},
            {"stop", {{"line", e.line + 1}, {"column", e.column + 1}, {"utf16_column", e16.column + 1}}}};
}

json::value expr_json(const SyntaxTree& tree, std::int32_t index, const LineIndex& lines) {
    if (index < 0) return nullptr;
    const Expr& e = tree.exprs[static_cast<std::size_t>(index)];
    json::object o{{"range", range_json(e.range(), lines)}};
    switch (e.kind) {
        case ExprKind::number:
            o["kind"] = "number";
            o["spelling"] = tree.slice(e.range());
            o["value"] = tree.number_value(e);
            o["decimal_point"] = (e.flags & token_flags::has_point) != 0;
            break;
        case ExprKind::variable:
            o["kind"] = "variable";
            o["index"] = expr_json(tree, e.a, lines);
            break;
        case ExprKind::negate:
        case ExprKind::plus:
        case ExprKind::bracket:
            o["kind"] = e.kind == ExprKind::negate ? "negate" : e.kind == ExprKind::plus ? "plus" : "bracket";
            o["operand"] = expr_json(tree, e.a, lines);
            break;
        case ExprKind::binary:
            o["kind"] = "binary";
            o["op"] = to_string(e.binary_op());
            o["left"] = expr_json(tree, e.a, lines);
            o["right"] = expr_json(tree, e.b, lines);
            break;
        case ExprKind::function: {
            o["kind"] = "function";
            o["name"] = to_string(e.function());
            json::array args{expr_json(tree, e.a, lines)};
            if (e.b >= 0) args.push_back(expr_json(tree, e.b, lines));
            o["arguments"] = std::move(args);
            break;
        }
    }
    return o;
}

json::object statement_json(const SyntaxTree& tree, std::int32_t index, const LineIndex& lines) {
    const Statement& s = tree.statements[static_cast<std::size_t>(index)];
    json::object o{{"kind", to_string(s.kind)}, {"range", range_json(s.range, lines)}};
    if (s.target >= 0) o["target"] = expr_json(tree, s.target, lines);
    if (s.value >= 0) o[s.kind == StatementKind::assign ? "value" : "condition"] = expr_json(tree, s.value, lines);
    if (s.label >= 0) o["label"] = expr_json(tree, s.label, lines);
    if (s.then_statement >= 0) o["then"] = statement_json(tree, s.then_statement, lines);
    if (s.kind == StatementKind::dprnt || s.kind == StatementKind::bprnt) o["text"] = tree.slice(s.text);
    return o;
}

json::object word_json(const TypedFile& file, std::uint32_t index, const LineIndex& lines) {
    const SyntaxTree& tree = file.tree();
    const Token& t = tree.tokens[index];
    json::object o{{"letter", std::string(1, t.letter)},
                   {"spelling", tree.spelling(t)},
                   {"range", range_json(tree.range(t), lines)}};
    if (t.has(token_flags::value_none)) {
        o["value"] = nullptr;
    } else if (t.has(token_flags::value_expr)) {
        o["expression"] = expr_json(tree, t.payload, lines);
    } else {
        o["value"] = tree.number_value(t);
        o["value_spelling"] = tree.value_spelling(t);
        o["decimal_point"] = t.has(token_flags::has_point);
        if (t.has(token_flags::decimal_comma)) o["decimal_comma"] = true;
    }
    if (t.has(token_flags::lower_case)) o["lower_case"] = true;
    return o;
}

json::value code_json(const TypedFile& file, const CodeRef& c, const LineIndex& lines) {
    json::object o = word_json(file, c.token, lines);
    if (c.info) {
        o["code"] = c.info->spelling;
        o["group"] = c.info->group;
        o["modal"] = c.info->modal;
        o["function"] = c.info->function.name();
    } else {
        o["code"] = nullptr;
    }
    return o;
}

json::object block_json(const TypedFile& file, std::size_t i, const LineIndex& lines) {
    const SyntaxTree& tree = file.tree();
    const BlockView v = file.block(i);
    const Block& b = v.block();
    json::object o{{"index", i}, {"kind", to_string(b.kind)}, {"range", range_json(v.range(), lines)}};
    if (b.has(block_flags::has_error)) o["error"] = true;
    if (const int level = v.block_delete_level()) o["block_delete"] = level;
    if (b.has(block_flags::has_eob)) o["eob"] = true;
    if (const auto n = v.word('N'); n && tree.tokens[*n].role() == Role::sequence) o["sequence"] = word_json(file, *n, lines);
    json::array g, m, axes, params, commas, comments, statements, drawing;
    for (const CodeRef& c : v.g_codes()) g.push_back(code_json(file, c, lines));
    for (const CodeRef& c : v.m_codes()) m.push_back(code_json(file, c, lines));
    for (const AxisWord& a : v.axis_words()) {
        json::object w = word_json(file, a.token, lines);
        w["axis"] = std::string(1, a.axis);
        w["incremental"] = a.incremental;
        axes.push_back(std::move(w));
    }
    for (const std::uint32_t p : v.parameters()) params.push_back(word_json(file, p, lines));
    for (const std::uint32_t p : v.words_with_role(Role::direct_drawing)) drawing.push_back(word_json(file, p, lines));
    for (const std::uint32_t c : v.comma_words()) commas.push_back(word_json(file, c, lines));
    for (const std::uint32_t c : v.comments()) {
        const Token& t = tree.tokens[c];
        json::object co{{"text", tree.spelling(t)}, {"range", range_json(tree.range(t), lines)}};
        if (t.has(token_flags::unclosed)) co["unclosed"] = true;
        comments.push_back(std::move(co));
    }
    for (const std::uint32_t s : v.statements()) statements.push_back(statement_json(tree, tree.tokens[s].payload, lines));
    auto put = [&](const char* key, json::array& a) {
        if (!a.empty()) o[key] = std::move(a);
    };
    put("g_codes", g);
    put("m_codes", m);
    put("axes", axes);
    put("parameters", params);
    put("direct_drawing", drawing);
    put("comma_words", commas);
    put("comments", comments);
    put("statements", statements);
    if (const auto call = v.subprogram_call())
        o["subprogram_call"] = {{"program", call->program}, {"repeats", call->repeats}, {"packed", call->packed}};
    if (const auto call = v.macro_call()) {
        json::object mc{{"modal", call->modal}, {"repeats", call->repeats}};
        mc["program"] = call->program ? json::value(*call->program) : json::value(nullptr);
        json::array args;
        for (const std::uint32_t a : call->arguments) args.push_back(word_json(file, a, lines));
        mc["arguments"] = std::move(args);
        o["macro_call"] = std::move(mc);
    }
    return o;
}

}  // namespace

json::value diagnostic_to_json(const Diagnostic& d, const LineIndex& lines) {
    json::object o{{"severity", to_string(d.severity)}, {"code", d.code}, {"message", d.message},
                   {"range", range_json(d.range, lines)}};
    if (!d.hint.empty()) o["hint"] = d.hint;
    return o;
}

json::value to_json(const TypedFile& file, const LineIndex& lines) {
    const SyntaxTree& tree = file.tree();
    json::array programs;
    for (const Program& p : file.programs()) {
        json::object po{{"first_block", p.first_block}, {"end_block", p.end_block}};
        po["number"] = p.number ? json::value(*p.number) : json::value(nullptr);
        programs.push_back(std::move(po));
    }
    json::array blocks;
    for (std::size_t i = 0; i < tree.block_count(); ++i) blocks.push_back(block_json(file, i, lines));
    json::array diagnostics;
    for (const Diagnostic& d : tree.diagnostics) diagnostics.push_back(diagnostic_to_json(d, lines));
    for (const Diagnostic& d : file.diagnostics()) diagnostics.push_back(diagnostic_to_json(d, lines));
    return json::object{{"dialect", file.dialect().id},
                        {"bytes", tree.text.size()},
                        {"programs", std::move(programs)},
                        {"blocks", std::move(blocks)},
                        {"diagnostics", std::move(diagnostics)}};
}

std::string to_text(const TypedFile& file, const LineIndex& lines) {
    const SyntaxTree& tree = file.tree();
    std::string out = fmt::format("dialect {}\n", file.dialect().id);
    for (const Program& p : file.programs())
        out += fmt::format("program {} blocks {}..{}\n", p.number ? fmt::format("O{:04}", *p.number) : "(none)",
                           p.first_block, p.end_block);
    for (std::size_t i = 0; i < tree.block_count(); ++i) {
        const BlockView v = file.block(i);
        const Block& b = v.block();
        if (b.kind == BlockKind::blank) continue;
        out += fmt::format("{:>4} {}", lines.utf8(b.begin).line + 1, to_string(b.kind));
        if (b.has(block_flags::has_error)) out += " !";
        out += ":";
        if (b.kind == BlockKind::tail) {
            out += fmt::format(" {} bytes ignored\n", v.range().size());
            continue;
        }
        for (const Token& t : v.tokens()) (out += ' ') += token_text(file, t);
        if (const auto call = v.subprogram_call())
            out += fmt::format(" => call O{:04} x{}", call->program, call->repeats);
        if (const auto call = v.macro_call())
            out += fmt::format(" => {} O{:04} x{} args {}", call->modal ? "modal-macro" : "macro",
                               call->program.value_or(-1), call->repeats, call->arguments.size());
        out += "\n";
    }
    for (const Diagnostic& d : tree.diagnostics) {
        const Position p = lines.utf8(d.range.begin);
        out += fmt::format("{}:{}: {} {}: {}\n", p.line + 1, p.column + 1, to_string(d.severity), d.code, d.message);
    }
    for (const Diagnostic& d : file.diagnostics()) {
        const Position p = lines.utf8(d.range.begin);
        out += fmt::format("{}:{}: {} {}: {}\n", p.line + 1, p.column + 1, to_string(d.severity), d.code, d.message);
    }
    return out;
}

}  // namespace kerf::ast
