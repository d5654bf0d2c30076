#include "fuzz/checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/json/parse.hpp>
#include <cmath>
#include <filesystem>
#include <vector>

#include "analyzer/analyze.hpp"
#include "analyzer/fix.hpp"
#include "analyzer/registry.hpp"
#include "ast/display.hpp"
#include "converter/convert.hpp"
#include "ast/input.hpp"
#include "ast/printer.hpp"
#include "ast/typed.hpp"
#include "dialects/dialect.hpp"
#include "formatter/format.hpp"
#include "formatter/style.hpp"
#include "formatter/verify.hpp"
#include "grammar/parse.hpp"
#include "interpreter/default_setup.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/trace_compare.hpp"
#include "interpreter/trace_json.hpp"
#include "machine/machine.hpp"
#include "project/config.hpp"

namespace kerf::fuzz {

namespace {

using interpreter::Event;
using interpreter::EventKind;

// The dialect table of fuzz_grammar: (byte + 6) % 9, so '0'..'8' pick these in order.
constexpr const char* kDialects[9] = {
    "fanuc-lathe-a", "fanuc-lathe-b", "fanuc-lathe-c", "spinner-lathe-a", "fanuc-mill",
    "adv400-mill",   "adv400-lathe",  "pcnc-mill",     "iso-legacy-mill",
};

const dialects::Dialect& dialect_of(std::uint8_t byte) {
    const dialects::Dialect* d = dialects::builtin_registry().find(kDialects[(static_cast<std::size_t>(byte) + 6) % 9]);
    return *d;   // every id of the table is built in (the test of this library runs them all)
}

// The options of a program input: the bits of byte 0 above the dialect choice.
unsigned options_of(std::uint8_t byte) { return static_cast<unsigned>(byte) / 9; }

// Small bounds: a fuzz input must run in milliseconds, and a loop reaches them quickly.
interpreter::Setup small_setup(interpreter::Setup s) {
    s.step_limit = 20'000;
    s.move_limit = 50'000;
    return s;
}

bool nan_in(const interpreter::Position& p) {
    return std::any_of(p.begin(), p.end(), [](double v) { return std::isnan(v); });
}

bool motion(EventKind k) {
    return k == EventKind::rapid || k == EventKind::linear || k == EventKind::arc_cw || k == EventKind::arc_ccw ||
           k == EventKind::thread;
}

// Checks every event as the run emits it; the first broken invariant is kept.
class CheckingSink : public interpreter::EventSink {
public:
    CheckingSink(const interpreter::ProgramSet& programs, std::string axes) : programs_(programs), axes_(std::move(axes)) {}
    void on_event(const Event& e) override {
        ++events_;
        if (broken_) return;
        broken_ = check(e);
        if (e.kind == EventKind::alarm) alarmed_ = true;
    }
    const Broken& broken() const { return broken_; }
    std::uint64_t events() const { return events_; }

private:
    Broken check(const Event& e) {
        if (static_cast<int>(e.kind) > static_cast<int>(EventKind::state)) return fmt::format("event kind {}", static_cast<int>(e.kind));
        if (e.source.file >= programs_.file_count()) return fmt::format("event source file {}", e.source.file);
        const std::size_t size = programs_.file(e.source.file).text_size();
        if (e.source.range.begin > e.source.range.end || e.source.range.end > size)
            return fmt::format("event source range {}..{} outside the file ({} bytes)", e.source.range.begin,
                               e.source.range.end, size);
        if (e.source.line == 0) return std::string("event source line 0");
        if (nan_in(e.start) || nan_in(e.end) || nan_in(e.machine_end))
            return fmt::format("NaN position in a {} event (line {})", interpreter::to_string(e.kind), e.source.line);
        for (const auto& [what, v] : {std::pair{"length", e.length_mm}, std::pair{"time", e.time_s}})
            if (std::isnan(v) || v < 0)
                return fmt::format("{} {} of a {} event (line {})", what, v, interpreter::to_string(e.kind), e.source.line);
        if (std::isnan(e.feed) || std::isnan(e.spindle_rpm) || std::isnan(e.radius) || std::isnan(e.lead_end))
            return fmt::format("NaN feed, speed, radius or lead in a {} event (line {})", interpreter::to_string(e.kind),
                               e.source.line);
        if (e.kind == EventKind::arc_cw || e.kind == EventKind::arc_ccw) {
            if (!e.center) return fmt::format("arc without a centre (line {})", e.source.line);
            if (nan_in(*e.center)) return fmt::format("NaN arc centre (line {})", e.source.line);
        }
        if (alarmed_ && motion(e.kind))
            return fmt::format("a {} after the alarm that stopped the run (line {})", interpreter::to_string(e.kind),
                               e.source.line);
        // The trace: every event is one line of valid JSON (the first ones, and every text event).
        if (events_ <= 256 || !e.text.empty()) {
            std::string line;
            interpreter::append_event_json(line, e, programs_, axes_);
            boost::system::error_code ec;
            boost::json::parse(line, ec);
            if (ec) return fmt::format("trace line is not JSON ({}): {}", ec.message(), line.substr(0, 200));
        }
        return std::nullopt;
    }

    const interpreter::ProgramSet& programs_;
    std::string axes_;
    Broken broken_;
    std::uint64_t events_ = 0;
    bool alarmed_ = false;
};

std::string axes_of(const dialects::Dialect& d, const interpreter::Setup& s) {
    return s.axis_order.empty() ? d.lexical.axes : s.axis_order;
}

// A dry run of the first program of `text` with every event checked, and the result's bounds.
Broken run_checked(std::string text, const dialects::Dialect& d, const interpreter::Setup& setup, bool lenient) {
    interpreter::ProgramSet programs;
    const std::uint32_t file = programs.add("fuzz.nc", std::move(text), d);
    const std::optional<interpreter::ProgramRef> main = programs.first_program(file);
    if (!main) return std::nullopt;
    CheckingSink sink(programs, axes_of(d, setup));
    interpreter::RunOptions options;
    options.lenient = lenient;
    const interpreter::RunResult r = interpreter::run(programs, *main, d, setup, sink, options);
    if (sink.broken()) return sink.broken();
    if (r.blocks > setup.step_limit + 1) return fmt::format("{} blocks run, the limit is {}", r.blocks, setup.step_limit);
    if (std::isnan(r.total_time_s) || std::isnan(r.feed_distance_mm) || std::isnan(r.rapid_distance_mm) || nan_in(r.final_position))
        return std::string("NaN in the run's summary");
    if (r.completed && !r.alarms.empty()) return std::string("the run completed with an alarm");
    return std::nullopt;
}

std::size_t error_count(const ast::SyntaxTree& tree) {
    return static_cast<std::size_t>(std::count_if(tree.diagnostics.begin(), tree.diagnostics.end(),
                                                  [](const ast::Diagnostic& d) { return d.severity == ast::Severity::error; }));
}

Broken lossless(const ast::SyntaxTree& tree, std::string_view text, const char* what) {
    if (ast::print(tree) != text) return fmt::format("{}: print(parse(text)) != text", what);
    if (const auto violation = ast::check_lossless(tree)) return fmt::format("{}: not lossless", what);
    return std::nullopt;
}

// A style from the option bits: each option takes one of its values, chosen by successive bits;
// `flags` spells it as kerf fmt's options, so that a finding can be replayed with the CLI.
struct FuzzStyle {
    formatter::Style style;
    std::string flags;
};

FuzzStyle style_of(unsigned bits, std::string_view text) {
    FuzzStyle out;
    std::size_t salt = text.size();
    const auto set = [&out](std::string_view key, std::string_view value) {
        (void)formatter::set_option(out.style, key, value);
        std::string flag(key);
        std::replace(flag.begin(), flag.end(), '_', '-');
        out.flags += fmt::format("{}--{} {}", out.flags.empty() ? "" : " ", flag, value);
    };
    for (const formatter::OptionInfo& o : formatter::options()) {
        if (o.values == "integer") {
            set(o.key, std::to_string((bits + salt) % 4));
            continue;
        }
        std::vector<std::string_view> values;
        for (std::size_t at = 0; at <= o.values.size();) {
            const std::size_t bar = std::min(o.values.find('|', at), o.values.size());
            values.push_back(o.values.substr(at, bar - at));
            at = bar + 1;
        }
        set(o.key, values[(bits + salt) % values.size()]);
        salt = salt * 31 + 7;
    }
    return out;
}

// A fixed program that moves, loops a little and calls, for the TOML targets: what a machine or a
// dialect changes shows in its run.
constexpr const char* kLatheProgram =
    "%\nO0001\nG21 G40 G97 G99\nT0101\nG50 S2000\nG96 S150 M03\nG00 X50. Z2. M08\nG71 U1. R0.5\n"
    "G71 P10 Q20 U0.2 W0.1 F0.2\nN10 G00 X20.\nG01 Z-10. F0.1\nG02 X30. Z-15. R5.\nN20 G01 X52.\nG70 P10 Q20\n"
    "G00 X100. Z100.\n#1=0\nWHILE [#1 LT 3] DO 1\nG01 U-1. W-1.\n#1=#1+1\nEND 1\nG04 X1.\nM30\n%\n";
constexpr const char* kMillProgram =
    "%\nO0001\nG21 G17 G40 G80 G90 G54\nT1 M06\nS1000 M03\nG00 X0 Y0 Z10.\nG43 H1 Z5.\nG01 Z-1. F100.\n"
    "G41 D1 X10. Y0\nG03 X0 Y10. R10.\nG02 X-10. Y0 I0 J-10.\nG40 G01 X0 Y0\nG81 R2. Z-5. F80.\nX20.\nG80\n"
    "#1=0\nWHILE [#1 LT 3] DO 1\nG91 G01 X1. Y1.\n#1=#1+1\nEND 1\nG90\nG04 P500\nM30\n%\n";

const char* program_for(const dialects::Dialect& d) {
    return d.machine == dialects::MachineKind::lathe ? kLatheProgram : kMillProgram;
}

std::size_t line_count(std::string_view text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1; }

Broken check_load_errors(const std::vector<dialects::LoadError>& errors, std::string_view text) {
    const std::size_t lines = line_count(text);
    for (const dialects::LoadError& e : errors) {
        if (e.message.empty()) return std::string("a load error without a message");
        if (e.line < 0 || static_cast<std::size_t>(e.line) > lines + 1 || e.column < 0)
            return fmt::format("load error at line {} column {} of a {}-line text: {}", e.line, e.column, lines, e.message);
    }
    return std::nullopt;
}

}  // namespace

Broken check_interpreter(std::string_view input) {
    if (input.size() < 2 || input.size() > kMaxProgramInput) return std::nullopt;
    const std::uint8_t byte = static_cast<std::uint8_t>(input[0]);
    const dialects::Dialect& d = dialect_of(byte);
    return run_checked(std::string(input.substr(1)), d, small_setup(interpreter::default_setup(d)), options_of(byte) & 1);
}

Broken check_analyzer(std::string_view input) {
    if (input.size() < 2 || input.size() > kMaxProgramInput) return std::nullopt;
    const std::uint8_t byte = static_cast<std::uint8_t>(input[0]);
    const dialects::Dialect& d = dialect_of(byte);
    const std::string text(input.substr(1));
    analyzer::CheckOptions options;
    options.max_findings_per_rule = options_of(byte) & 1 ? 3 : 0;
    const std::vector<analyzer::Finding> findings =
        analyzer::check_text("fuzz.nc", text, d, small_setup(interpreter::default_setup(d)), options);
    const analyzer::Registry& registry = analyzer::builtin_rules();
    std::map<std::string, std::size_t> per_rule;
    for (const analyzer::Finding& f : findings) {
        if (f.range.begin > f.range.end || f.range.end > text.size())
            return fmt::format("{} range {}..{} outside the text ({} bytes)", f.rule, f.range.begin, f.range.end, text.size());
        if (!registry.find(f.rule)) return fmt::format("finding of an unknown rule {}", f.rule);
        if (f.message.empty()) return fmt::format("{} without a message", f.rule);
        if (options.max_findings_per_rule > 0 && ++per_rule[f.rule] > options.max_findings_per_rule + 1)
            return fmt::format("{} findings of {} with a cap of {}", per_rule[f.rule], f.rule, options.max_findings_per_rule);
        if (f.fix)
            for (const analyzer::TextEdit& e : f.fix->edits)
                if (e.range.begin > e.range.end || e.range.end > text.size())
                    return fmt::format("{} fix edit {}..{} outside the text", f.rule, e.range.begin, e.range.end);
    }
    const analyzer::FixResult fixed = analyzer::apply_fixes(text, findings);
    const ast::SyntaxTree before = grammar::parse(text, d.lexical);
    const ast::SyntaxTree after = grammar::parse(fixed.text, d.lexical);
    if (auto broken = lossless(after, fixed.text, "the fixed text")) return broken;
    if (error_count(after) > error_count(before))
        return fmt::format("the fixes ({}) left {} syntax errors where the text had {}", fixed.applied, error_count(after),
                           error_count(before));
    return std::nullopt;
}

static Broken check_formatter_with(const dialects::Dialect& d, const std::string& text, const formatter::Style& style) {
    const interpreter::Setup setup = small_setup(interpreter::default_setup(d));
    const formatter::FormatContext context{setup.calculator_decimal};
    ast::SyntaxTree tree = grammar::parse(text, d.lexical);
    // kerf fmt and the language server format only texts without syntax errors (project/format.cpp
    // refuses the others); what the library prints for a broken text is not a promise (a comment
    // left open on its line is not reprinted the same twice: fuzz/README.md, findings).
    if (error_count(tree) > 0) return std::nullopt;
    const ast::TypedFile typed = ast::TypedFile::bind(tree, d);
    const formatter::FormatResult first = formatter::format(typed, style, context);
    if (!first.text) return std::nullopt;   // refused (a renumbering it cannot follow): nothing to check
    ast::SyntaxTree again = grammar::parse(*first.text, d.lexical);
    if (auto broken = lossless(again, *first.text, "the formatted text")) return broken;
    const ast::TypedFile typed_again = ast::TypedFile::bind(again, d);
    const formatter::FormatResult second = formatter::format(typed_again, style, context);
    if (!second.text) return std::string("the formatted text is refused when formatted again");
    if (*second.text != *first.text) {
        const auto at = std::mismatch(first.text->begin(), first.text->end(), second.text->begin(), second.text->end());
        const std::size_t offset = static_cast<std::size_t>(at.first - first.text->begin());
        // The two texts around the first difference, escaped, so that the report says what changed.
        const auto around = [&](const std::string& t) {
            const std::size_t from = offset > 12 ? offset - 12 : 0;
            return ast::printable(t.substr(from, 40));
        };
        return fmt::format("not idempotent: the second pass differs at byte {} of {}: '{}' then '{}'", offset, first.text->size(),
                           around(*first.text), around(*second.text));
    }
    // The input has no syntax error: the runs must agree.
    if (*first.text == text) return std::nullopt;
    formatter::VerifyOptions v;
    v.dialect = &d;
    v.setup = setup;
    const formatter::VerifyResult result = formatter::verify("fuzz.nc", text, *first.text, v);
    if (result.difference)
        return fmt::format("--verify: event {} (input line {}, output line {}): {}", result.difference->event,
                           result.difference->input_line, result.difference->output_line, result.difference->what);
    return std::nullopt;
}

Broken check_formatter(std::string_view input) {
    if (input.size() < 2 || input.size() > kMaxProgramInput) return std::nullopt;
    const std::uint8_t byte = static_cast<std::uint8_t>(input[0]);
    const dialects::Dialect& d = dialect_of(byte);
    const std::string text(input.substr(1));
    const FuzzStyle style = style_of(options_of(byte), text);
    Broken broken = check_formatter_with(d, text, style.style);
    // How to replay it with the CLI, on the input without its first byte (in a folder of its own).
    if (broken) *broken += fmt::format(" [kerf fmt --verify --dialect {} {}]", d.id, style.flags);
    return broken;
}

Broken check_converter(std::string_view input) {
    if (input.size() < 2 || input.size() > kMaxProgramInput) return std::nullopt;
    const std::uint8_t byte = static_cast<std::uint8_t>(input[0]);
    const dialects::Dialect& from = dialect_of(byte);
    const unsigned options = options_of(byte);
    const dialects::Dialect& to = *dialects::builtin_registry().find(kDialects[options % 9]);
    const std::string text(input.substr(1));
    ast::SyntaxTree tree = grammar::parse(text, from.lexical);
    const ast::TypedFile typed = ast::TypedFile::bind(tree, from);
    // One machine description, each side in its dialect's reading (project::Project::setup).
    const machine::Machine m = machine::default_machine_for(from);
    const interpreter::Setup source = small_setup(interpreter::make_setup(machine::resolve_for_dialect(m, from)));
    const interpreter::Setup target = small_setup(interpreter::make_setup(machine::resolve_for_dialect(m, to)));
    converter::Options o;
    o.incremental = (options / 9) % 2 ? converter::IncrementalStyle::letters : converter::IncrementalStyle::g91;
    o.expand = options / 18 > 0;
    o.from = converter::reading_of(from, source);
    o.to = converter::reading_of(to, target);
    o.setup = source;
    const converter::Conversion c = converter::convert(typed, to, o);
    std::uint32_t at = 0;
    for (std::size_t i = 0; i < c.edits.size(); ++i) {
        const converter::Edit e = c.edits[i];
        if (e.range.begin < at || e.range.end < e.range.begin || e.range.end > tree.text.size())
            return fmt::format("edit {} ({}..{}) out of order, overlapping or outside the text ({} bytes)", i, e.range.begin,
                               e.range.end, tree.text.size());
        at = e.range.end;
    }
    const std::string out = converter::apply(tree.text, c.edits);
    if (from.machine != to.machine) {
        if (out != tree.text) return std::string("a conversion between a lathe and a mill dialect changed the text");
        return std::nullopt;
    }
    const ast::SyntaxTree converted = grammar::parse(out, to.lexical);
    if (auto broken = lossless(converted, out, "the converted text")) return broken;
    if (error_count(tree) > 0 || !c.clean()) return std::nullopt;
    if (error_count(converted) > 0)
        return fmt::format("a clean conversion {} → {} has {} syntax errors in the target", from.id, to.id, error_count(converted));
    interpreter::CompareOptions compare;
    compare.profile = interpreter::CompareProfile::motion;
    compare.tolerance = 0.001;
    const interpreter::TraceComparison r = interpreter::compare_runs({"fuzz.nc", text, &from, source, {}},
                                                                     {"fuzz.nc", out, &to, target, {}}, compare);
    if (r.difference)
        return fmt::format("{} → {}: motion event {} (input line {}, output line {}): {}", from.id, to.id, r.difference->event,
                           r.difference->input_line, r.difference->output_line, r.difference->what);
    return std::nullopt;
}

Broken check_machine_toml(std::string_view input) {
    if (input.size() > kMaxProgramInput) return std::nullopt;
    const machine::LoadResult loaded = machine::load_machine_text(input, "fuzz.toml");
    if (auto broken = check_load_errors(loaded.errors, input)) return broken;
    if (!loaded.machine || !loaded.errors.empty()) return std::nullopt;
    for (const std::string& id : dialects::builtin_registry().ids()) {
        const dialects::Dialect& d = *dialects::builtin_registry().find(id);
        const machine::Machine m = machine::resolve_for_dialect(*loaded.machine, d);
        if (m.kind != d.machine) continue;   // the CLI warns and runs; a lathe program on a mill proves little
        if (auto broken = run_checked(program_for(d), d, small_setup(interpreter::make_setup(m)), false))
            return fmt::format("machine for {}: {}", id, *broken);
    }
    return std::nullopt;
}

Broken check_dialect_toml(std::string_view input) {
    if (input.size() > kMaxProgramInput) return std::nullopt;
    dialects::Registry registry = dialects::builtin_registry();
    const std::vector<std::string> before = registry.ids();
    const std::vector<dialects::LoadError> errors = registry.add_text(input, "fuzz.toml");
    if (auto broken = check_load_errors(errors, input)) return broken;
    for (const std::string& id : registry.ids()) {
        if (std::find(before.begin(), before.end(), id) != before.end()) continue;
        const dialects::Dialect& d = *registry.find(id);
        const std::string program = program_for(d);
        ast::SyntaxTree tree = grammar::parse(program, d.lexical);
        if (auto broken = lossless(tree, program, "the sample program")) return fmt::format("dialect {}: {}", id, *broken);
        (void)ast::TypedFile::bind(tree, d);
        if (auto broken = run_checked(program, d, small_setup(interpreter::default_setup(d)), true))
            return fmt::format("dialect {}: {}", id, *broken);
    }
    return std::nullopt;
}

Broken check_input(std::string_view input) {
    if (input.size() < 3 || input.size() > kMaxProgramInput) return std::nullopt;
    // Byte 0: the line limit (0 = none, else 1..255 bytes); byte 1: where the pieces split.
    ast::InputLimits limits;
    limits.max_line_bytes = static_cast<unsigned char>(input[0]);
    const std::size_t step = 1 + static_cast<unsigned char>(input[1]) % 64;
    const std::string_view bytes = input.substr(2);
    const ast::DecodedInput whole = ast::decode_input(std::string(bytes), limits);
    ast::InputScanner scanner(limits);
    for (std::size_t at = 0; at < bytes.size(); at += step) scanner.feed(bytes.substr(at, step));
    const ast::DecodedInput pieces = scanner.finish();
    if (pieces.encoding != whole.encoding || pieces.bom != whole.bom)
        return fmt::format("the scanner says {}, decode_input {}", ast::to_string(pieces.encoding), ast::to_string(whole.encoding));
    for (const ast::InputProblem& p : whole.problems)
        if (p.message.empty()) return std::string("a decoder problem without a message");
    if (whole.refused() && !whole.text.empty()) return std::string("a refused input with a text");
    if (whole.encoding != ast::Encoding::utf8) {
        // The scanner leaves UTF-16/32 to decode_input; a clean transcoding round-trips.
        const bool bad = std::any_of(whole.problems.begin(), whole.problems.end(),
                                     [](const ast::InputProblem& p) { return p.kind == ast::InputProblemKind::bad_encoding; });
        if (!whole.refused() && !bad && ast::encode_output(whole.text, whole.encoding, whole.bom) != bytes)
            return fmt::format("{} text does not encode back into its bytes", ast::to_string(whole.encoding));
        return std::nullopt;
    }
    if (pieces.problems.size() != whole.problems.size())
        return fmt::format("the scanner finds {} problem(s), decode_input {}", pieces.problems.size(), whole.problems.size());
    for (std::size_t i = 0; i < whole.problems.size(); ++i)
        if (pieces.problems[i].kind != whole.problems[i].kind || pieces.problems[i].line != whole.problems[i].line ||
            pieces.problems[i].message != whole.problems[i].message)
            return fmt::format("problem {}: the scanner says '{}' (line {}), decode_input '{}' (line {})", i,
                               pieces.problems[i].message, pieces.problems[i].line, whole.problems[i].message,
                               whole.problems[i].line);
    if (!whole.refused() && whole.text != bytes) return std::string("UTF-8 input not returned byte for byte");
    return std::nullopt;
}

Broken check_kerf_toml(std::string_view input) {
    if (input.size() > kMaxProgramInput) return std::nullopt;
    const std::filesystem::path file = "/fuzz/project/.kerf.toml";
    const project::ConfigResult r = project::parse_config(input, file);
    const std::size_t lines = line_count(input);
    for (const project::Problem& p : r.problems) {
        if (p.message.empty()) return std::string("a .kerf.toml problem without a message");
        if (p.file != file.string()) return fmt::format("a problem names '{}'", p.file);
        if (p.line < 0 || static_cast<std::size_t>(p.line) > lines + 1 || p.column < 0)
            return fmt::format("problem at line {} column {} of a {}-line text: {}", p.line, p.column, lines, p.message);
    }
    if (r.config.file != file) return std::string("the config does not name its file");
    return std::nullopt;
}

}  // namespace kerf::fuzz
