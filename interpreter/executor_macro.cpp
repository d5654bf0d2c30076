// Macro B statements and G65 calls (reference/dialects.md §3.7; FANUC custom macro B).
#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"
#include "interpreter/macro/arguments.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {

// DPRNT[...] output ([FANUC] "External output commands"): characters are printed as written, `*`
// prints a space, blanks are not printed, and `#n[ab]` prints variable n with a integer digits and
// b decimals (`#n` without a format: the value as is). A vacant variable prints as 0.
std::string format_print(std::string_view text, const macro::Variables& variables) {
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c != '#') {
            if (c == '*') out += ' ';
            else if (c != ' ' && c != '\t') out += c;
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        // Saturated: #2025555555555 is no variable (read gives vacant), and must not overflow an int.
        constexpr int kPastEveryVariable = 100'000'000;
        int number = 0;
        while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) {
            const int digit = text[j++] - '0';
            number = number >= kPastEveryVariable ? kPastEveryVariable : number * 10 + digit;
        }
        int decimals = -1;
        if (j + 1 < text.size() && text[j] == '[') {
            const std::size_t close = text.find(']', j);
            if (close != std::string_view::npos && close > j + 1) {
                decimals = text[close - 1] - '0';
                j = close + 1;
            }
        }
        const auto value = variables.read(number);
        const double v = value ? value->or_zero() : 0.0;
        out += decimals >= 0 ? fmt::format("{:.{}f}", v, decimals) : fmt::format("{}", v);
        i = j;
    }
    return out;
}

}  // namespace

// not_mine: the rest of the block runs; done: it ends here (a jump, a loop, a call, IF [..] whose
// words are skipped); stopped: an alarm.
Outcome Executor::execute_statements(Frame& frame, const BlockContext& ctx) {
    const ast::SyntaxTree& tree = ctx.view.tree();
    if (ctx.scan.statements) {
        for (const std::uint32_t ti : ctx.view.statements()) {
            const ast::Statement& s = tree.statements[static_cast<std::size_t>(tree.tokens[ti].payload)];
            if (const Outcome o = unless_stopped(execute_statement(frame, ctx, s)); o != Outcome::not_mine) return o;
        }
    }
    if (!ctx.scan.macro_call) return Outcome::not_mine;
    if (const auto call = ctx.view.macro_call()) return start_macro_call(ctx, *call);
    return Outcome::not_mine;
}

Outcome Executor::execute_statement(Frame& frame, const BlockContext& ctx, const ast::Statement& s) {
    const ast::SyntaxTree& tree = ctx.view.tree();
    auto fail = [&](const macro::Error& e) {
        alarm(ctx, e.alarm, e.message);
        return Outcome::stopped;
    };
    auto condition = [&]() -> std::optional<bool> {   // the value, or nullopt after its alarm
        const macro::ConditionResult c = macro::evaluate_condition(tree, s.value, variables_, macro_options(state_, false));
        if (c.error) {
            fail(*c.error);
            return std::nullopt;
        }
        return c.value;
    };
    auto label_value = [&]() -> std::optional<double> {
        const macro::Result r = macro::evaluate(tree, s.label, variables_, macro_options(state_, false));
        if (r.error) {
            fail(*r.error);
            return std::nullopt;
        }
        return r.value.vacant ? 0.0 : r.value.number;
    };
    switch (s.kind) {
        case ast::StatementKind::assign: {
            ExecutorSystemVariables system(*this, ctx);   // the block's: #3000 raises its alarm here
            if (const auto e = macro::assign(tree, s, variables_, system, macro_options(state_, false))) return fail(*e);
            return unless_stopped(Outcome::not_mine);   // #3006 may stop the run
        }
        case ast::StatementKind::if_then: {
            const auto c = condition();
            if (!c) return Outcome::stopped;
            if (*c) return execute_statement(frame, ctx, tree.statements[static_cast<std::size_t>(s.then_statement)]);
            return Outcome::not_mine;
        }
        case ast::StatementKind::if_words: {
            // [Haas] IF [...] G65 P9725: the block's words run only when the condition holds.
            const auto c = condition();
            if (!c) return Outcome::stopped;
            return *c ? Outcome::not_mine : Outcome::done;
        }
        case ast::StatementKind::if_goto:
        case ast::StatementKind::goto_: {
            if (s.kind == ast::StatementKind::if_goto) {
                const auto c = condition();
                if (!c) return Outcome::stopped;
                if (!*c) return Outcome::not_mine;
            }
            const auto n = label_value();
            if (!n) return Outcome::stopped;
            const auto target = find_label(frame, std::round(*n));
            if (!target) {
                alarm(ctx, 128, fmt::format("GOTO {}: no sequence number N{} in this program (alarm 128)", *n, *n));
                return Outcome::stopped;
            }
            frame.block = *target;
            frame.loops.clear();   // a jump out of a loop leaves it
            return Outcome::done;
        }
        case ast::StatementKind::while_do:
        case ast::StatementKind::do_: {
            const auto m = label_value();
            if (!m) return Outcome::stopped;
            if (*m < 1 || *m > 3) {
                alarm(ctx, 126, fmt::format("DO {}: the loop number must be 1, 2 or 3 (alarm 126)", *m));
                return Outcome::stopped;
            }
            const bool enter = s.kind == ast::StatementKind::do_ ? true : [&] {
                const auto c = condition();
                return c.value_or(false);
            }();
            if (stopped_) return Outcome::stopped;
            if (enter) {
                if (frame.loops.empty() || frame.loops.back().do_block != ctx.scan.block) {
                    if (frame.loops.size() >= 3) {
                        alarm(ctx, 124, "WHILE/DO nested deeper than 3 (alarm 124)");
                        return Outcome::stopped;
                    }
                    frame.loops.push_back({ctx.scan.block, static_cast<int>(*m)});
                }
                return Outcome::not_mine;
            }
            // Condition false: continue after the matching END m.
            if (!frame.loops.empty() && frame.loops.back().do_block == ctx.scan.block) frame.loops.pop_back();
            const auto end = find_end(frame, ctx.scan.block, static_cast<int>(*m));
            if (!end) {
                alarm(ctx, 124, fmt::format("DO {} without END {} (alarm 124)", *m, *m));
                return Outcome::stopped;
            }
            frame.block = *end + 1;
            return Outcome::done;
        }
        case ast::StatementKind::end: {
            const auto m = label_value();
            if (!m) return Outcome::stopped;
            if (frame.loops.empty() || frame.loops.back().label != static_cast<int>(*m)) {
                alarm(ctx, 124, fmt::format("END {} without its DO (alarm 124)", *m));
                return Outcome::stopped;
            }
            frame.block = frame.loops.back().do_block;   // back to WHILE: the condition is tested again
            return Outcome::done;
        }
        case ast::StatementKind::dprnt:
        case ast::StatementKind::bprnt: {
            Event e = event_at(EventKind::message, ctx);
            e.text = format_print(tree.slice(s.text), variables_);
            emit(e);
            return Outcome::not_mine;
        }
        case ast::StatementKind::popen:
        case ast::StatementKind::pclos:
            return Outcome::not_mine;
    }
    return Outcome::not_mine;
}

std::optional<std::uint32_t> Executor::find_end(const Frame& frame, std::uint32_t from, int label) const {
    const LoadedFile& file = file_of(frame);
    for (std::uint32_t b = from + 1; file.in_program(frame.program.program, b); ++b) {
        const ast::BlockView view = file.block(b);
        const ast::SyntaxTree& tree = view.tree();
        for (const std::uint32_t ti : view.statements()) {
            const ast::Statement& s = tree.statements[static_cast<std::size_t>(tree.tokens[ti].payload)];
            if (s.kind != ast::StatementKind::end) continue;
            const ast::Expr& e = tree.exprs[static_cast<std::size_t>(s.label)];
            if (e.kind == ast::ExprKind::number && std::lround(tree.number_value(e)) == label) return b;
        }
    }
    return std::nullopt;
}

std::optional<std::vector<std::pair<int, macro::Value>>> Executor::macro_arguments(const BlockContext& ctx, const ast::MacroCall& call) {
    const ast::SyntaxTree& tree = ctx.view.tree();
    macro::ArgumentMapper mapper;
    std::vector<std::pair<int, macro::Value>> arguments;
    for (const std::uint32_t ti : call.arguments) {
        const ast::Token& t = tree.tokens[ti];
        const int number = mapper.variable(t.letter);
        if (!number) continue;
        macro::Value v = macro::Value::vacant_value();
        if (t.has(ast::token_flags::value_expr)) {
            const macro::Result r = macro::evaluate(tree, t.payload, variables_, macro_options(state_, true));
            if (r.error) {
                alarm(ctx, r.error->alarm, r.error->message);
                return std::nullopt;
            }
            v = r.value;
        } else if (t.is_number()) {
            // Without a decimal point an argument counts least input increments unless the
            // machine has calculator-type input ([FANUC]: G65 X10 gives #24 = 0.010 on IS-B).
            const double n = tree.number_value(t);
            const bool increments = !t.has(ast::token_flags::has_point) && !setup_.calculator_decimal;
            v = increments ? macro::Value::of_increments(n * increment(state_, t.letter)) : macro::Value::of(n);
        }
        arguments.emplace_back(number, v);
    }
    return arguments;
}

bool Executor::push_macro_frame(const BlockContext& ctx, std::int64_t program,
                                std::int64_t repeats, const std::vector<std::pair<int, macro::Value>>& arguments,
                                bool modal) {
    const auto target = programs_.find_or_load(program, ctx.frame.program.file);
    if (!target) {
        if (!skip_resident_call(ctx, program, modal ? "G66" : "G65"))
            alarm(ctx, 78, fmt::format("G6{}: program O{:04} not found (alarm 078)", modal ? 6 : 5, program));
        return false;
    }
    int macros = 0;
    for (const Frame& f : frames_) macros += f.macro;
    if (macros >= setup_.max_macro_depth) {
        alarm(ctx, 77, fmt::format("macro calls nested deeper than {} (alarm 077)", setup_.max_macro_depth));
        return false;
    }
    // A new level of local variables, set from the arguments (vacant where not given).
    variables_.push_level();
    for (const auto& [number, value] : arguments) variables_.write(number, value);
    Event e = event_at(EventKind::call, ctx);
    e.code = static_cast<int>(program);
    e.text = modal ? "G66 modal macro call" : "G65 macro call";
    emit(e);
    Frame sub;
    sub.program = *target;
    sub.block = sub.start_block = program_of(sub).first_block;
    sub.repeats_left = repeats;
    sub.macro = true;
    sub.modal_macro = modal;
    frames_.push_back(sub);
    return true;
}

// G65 P_ L_ arguments: the block ends here (done: the call started or was skipped; stopped: an
// alarm); G66 is not_mine (execute_block remembers it).
Outcome Executor::start_macro_call(const BlockContext& ctx, const ast::MacroCall& call) {
    if (call.modal) return Outcome::not_mine;
    if (!call.program) {
        alarm(ctx, 76, "G65 without a program number P (alarm 076)");
        return Outcome::stopped;
    }
    const auto arguments = macro_arguments(ctx, call);
    if (arguments) push_macro_frame(ctx, *call.program, call.repeats, *arguments, false);
    return unless_stopped(Outcome::done);
}

}  // namespace kerf::interpreter
