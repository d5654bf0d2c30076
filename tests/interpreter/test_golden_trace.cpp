// Golden trace tests of the reference examples: what the interpreter does with each example, as a
// compact text that a person can check against the example's `(EXPECTED: …)` header and the
// reference (tests/golden/trace/REVIEW.md).
//
// tests/golden/trace/<example>.trace (the example is <example>.nc) starts with a header of '#'
// lines, written by hand: `# example:`, `# dialect:` (the mapping of tests/example_dialects.hpp),
// every `(EXPECTED: …)` line of the example verbatim after "# ", `# status:`, `# lenient:` (whether
// lenient running mattered), and `# checked:` / `# not yet:` / `# DISAGREES:` lines that say which
// expected numbers were verified by hand against which trace lines. The rest of the file (the body) is the rendered
// trace, compared exactly. The example runs with default_setup(dialect) and RunOptions{lenient}.
//
// KERF_UPDATE_GOLDEN=1 rewrites the bodies (the header is kept); review the `git diff` of
// tests/golden/trace and re-check the `# checked:` lines before committing — never accept output
// that was not checked. Goldens whose `# status:` says FAILS hold what the reference says where kerf
// disagrees; they are never rewritten. A header line `# TODO` (left by a new skeleton) fails the test.
// KERF_UPDATE_GOLDEN=1 KERF_TRACE_NEW=a.nc,b.nc writes skeletons for new examples.
#include <catch2/catch.hpp>

#include <map>
#include <set>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"
#include "interpreter/default_setup.hpp"
#include "interpreter/event_fields.hpp"
#include "interpreter/interpreter.hpp"
#include "tests/example_dialects.hpp"
#include "tests/golden_diff.hpp"

namespace fs = std::filesystem;
using namespace kerf;
using interpreter::Event;
using interpreter::EventKind;
using interpreter::Position;

namespace {

using kerf::test::line_diff;
using kerf::test::split_lines;

constexpr std::uint64_t kStepLimit = 20'000;   // the examples are short; a loop ends in an alarm

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}


// --- rendering -----------------------------------------------------------------------------------

// Rounded to 0.001, without trailing zeros, never "-0".
std::string num(double v) {
    double r = std::round(v * 1000.0) / 1000.0;
    if (r == 0) r = 0;
    std::string s = fmt::format("{:.3f}", r);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

struct Run {
    interpreter::RunResult result;
    std::vector<Event> events;
};

Run run_example(const std::string& name, const std::string& text, const dialects::Dialect& dialect, bool lenient) {
    interpreter::ProgramSet programs;
    const auto file = programs.add(name, text, dialect);
    Run r;
    const auto main = programs.first_program(file);
    if (!main) return r;
    interpreter::Setup setup = interpreter::default_setup(dialect);
    setup.step_limit = kStepLimit;
    interpreter::VectorSink sink;
    interpreter::RunOptions options;
    options.lenient = lenient;
    r.result = interpreter::run(programs, *main, dialect, setup, sink, options);
    r.events = std::move(sink.events);
    return r;
}

class Renderer {
public:
    Renderer(const dialects::Dialect& dialect, const Run& run) : dialect_(dialect) {
        // The main axes of the machine kind always; the dialect's other axes when the run uses them.
        const bool lathe = dialect.machine == dialects::MachineKind::lathe;
        for (std::size_t a = 0; a < interpreter::kAxisCount; ++a) {
            const char letter = interpreter::kAxisLetters[a];
            const bool main_axis = letter == 'X' || letter == 'Z' || (!lathe && letter == 'Y');
            bool used = main_axis;
            if (!used && dialect.lexical.is_axis(letter)) {
                for (const Event& e : run.events)
                    if (std::fabs(e.end[a]) > 5e-4 || std::fabs(e.start[a]) > 5e-4 || std::fabs(e.machine_end[a]) > 5e-4)
                        used = true;
                if (std::fabs(run.result.final_position[a]) > 5e-4) used = true;
            }
            if (used) axes_.push_back(a);
        }
    }

    std::string position(const Position& p) const {
        std::string s;
        for (const std::size_t a : axes_) {
            if (!s.empty()) s += ' ';
            s += interpreter::kAxisLetters[a];
            s += num(p[a]);
        }
        return s;
    }

    bool machine_differs(const Event& e) const {
        for (const std::size_t a : axes_)
            if (num(e.machine_end[a]) != num(e.end[a])) return true;
        return false;
    }

    std::string event(const Event& e) const {
        std::string s = fmt::format("{:>4} {}", e.source.line, interpreter::to_string(e.kind));
        if (interpreter::is_motion(e.kind)) {
            s += ' ' + position(e.end);
            if (machine_differs(e)) s += " M(" + position(e.machine_end) + ")";
            if (e.center) {
                // The centre on the main axes (X as diameter on lathes, like the end point).
                std::string c;
                for (const std::size_t a : axes_) {
                    if (a >= 3) continue;
                    if (!c.empty()) c += ' ';
                    c += interpreter::kAxisLetters[a];
                    c += num((*e.center)[a]);
                }
                s += " C(" + c + ") R" + num(e.radius);
            }
            if (e.kind != EventKind::rapid) {
                s += " F" + num(e.feed) + (e.feed_per_rev ? "/rev" : "/min");
                if (e.feed_per_rev) s += " n=" + num(e.spindle_rpm);
                if (e.kind == EventKind::thread && e.lead_end != e.feed) s += " lead_end=" + num(e.lead_end);
            }
            s += " len=" + num(e.length_mm) + " t=" + num(e.time_s) + "s";
            return s;
        }
        switch (e.kind) {
            case EventKind::dwell: s += ' ' + num(e.time_s) + "s"; break;
            case EventKind::tool_change:
                s += fmt::format(" T{}", e.tool);
                if (dialect_.machine == dialects::MachineKind::lathe) s += fmt::format(" offset {}", e.code);
                break;
            case EventKind::spindle: s += fmt::format(" M{} n={}", e.code, num(e.spindle_rpm)); break;
            case EventKind::coordinate_change:
                s += " (" + e.text + ") " + position(e.end) + " M(" + position(e.machine_end) + ")";
                break;
            case EventKind::call: s += fmt::format(" O{:04}", e.code); break;
            case EventKind::alarm: s += fmt::format(" {} {}", e.code, e.text); break;
            case EventKind::message: s += ' ' + e.text; break;
            default:
                if (e.code) s += fmt::format(" M{}", e.code);
                if (!e.text.empty()) s += ' ' + e.text;
                break;
        }
        return s;
    }

private:
    const dialects::Dialect& dialect_;
    std::vector<std::size_t> axes_;
};

std::string render(const dialects::Dialect& dialect, const Run& run, const Run& strict) {
    const Renderer r(dialect, run);
    std::string out;
    std::size_t lenient_blocks = 0;
    for (const Event& e : run.events) {
        out += r.event(e) + '\n';
        if (e.kind == EventKind::message && e.text.find("(lenient)") != std::string::npos) ++lenient_blocks;
    }
    const interpreter::RunResult& res = run.result;
    out += "--- summary\n";
    if (std::any_of(run.events.begin(), run.events.end(), [](const Event& e) { return e.inch; }))
        out += "units inch (positions, centres and feeds of the events in inches; len and the summary's distances in mm)\n";
    out += "final " + r.position(res.final_position) + '\n';
    out += std::string("completed ") + (res.completed ? "yes" : "no") + '\n';
    if (res.alarms.empty()) out += "alarms none\n";
    for (const Event& a : res.alarms) out += fmt::format("alarm {} at line {}: {}\n", a.code, a.source.line, a.text);
    out += fmt::format("blocks {}\n", res.blocks);
    out += "time " + num(res.total_time_s) + "s, feed " + num(res.feed_distance_mm) + "mm, rapid " +
           num(res.rapid_distance_mm) + "mm\n";
    out += "tools";
    if (res.tools.empty()) out += " none";
    for (const int t : res.tools) out += fmt::format(" T{}", t);
    out += '\n';
    if (!res.time_per_tool_s.empty()) {
        out += "time per tool";
        for (const auto& [tool, seconds] : res.time_per_tool_s) out += fmt::format(" T{} {}s", tool, num(seconds));
        out += '\n';
    }
    if (lenient_blocks == 0) {
        out += "lenient: no effect (no block with syntax errors was run)\n";
    } else {
        out += fmt::format("lenient: {} block(s) with syntax errors run without their defective words", lenient_blocks);
        const auto it = std::find_if(strict.events.begin(), strict.events.end(),
                                     [](const Event& e) { return e.kind == EventKind::alarm; });
        if (it != strict.events.end()) out += fmt::format("; a strict run stops at line {} ({})", it->source.line, it->text);
        out += '\n';
    }
    return out;
}

// What the golden body shows of each field of the trace (interpreter/event_fields.hpp, issue 13:
// one list of fields): a field added to the list fails the test below until the renderer shows it
// or this table says why the golden files leave it out.
const std::map<std::string_view, std::string_view> kRenderedFields = {
    {"kind", "shown"}, {"file", "left out: every example is one file"}, {"line", "shown"}, {"end", "shown"},
    {"units", "shown once, in the summary, for runs with inch events"}, {"machine", "shown as M(...) where it differs from end"},
    {"start", "left out: the previous event's end"}, {"length_mm", "shown as len="}, {"time_s", "shown as t= and on dwells"},
    {"feed", "shown as F"}, {"lead_end", "shown on G34 threads"}, {"feed_per_rev", "shown as /rev or /min"},
    {"spindle_rpm", "shown as n= on per-revolution moves and spindle events"},
    {"spindle_running", "left out: a stopped spindle shows in the spindle event before (M05)"},
    {"center", "shown as C(...)"}, {"radius", "shown as R"}, {"tool", "shown on tool changes"},
    {"code", "shown per kind"}, {"text", "shown per kind"},
};

// --- golden files --------------------------------------------------------------------------------

struct Golden {
    std::vector<std::string> header;   // the '#' lines, without their line breaks
    std::string body;
};

Golden read_golden(const fs::path& path) {
    Golden g;
    const std::string all = read_text(path);
    std::size_t pos = 0;
    while (pos < all.size() && all[pos] == '#') {
        const std::size_t eol = all.find('\n', pos);
        g.header.push_back(all.substr(pos, eol == std::string::npos ? std::string::npos : eol - pos));
        pos = eol == std::string::npos ? all.size() : eol + 1;
    }
    g.body = all.substr(pos);
    return g;
}

std::string header_value(const Golden& g, std::string_view key) {
    for (const std::string& line : g.header)
        if (line.rfind(key, 0) == 0) return line.substr(key.size());
    return {};
}

// The `(EXPECTED: …)` lines of the example, as written.
std::vector<std::string> expected_lines(const std::string& text) {
    std::vector<std::string> out;
    for (std::string line : split_lines(text)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (line.rfind("(EXPECTED", 0) == 0) out.push_back(line);
    }
    return out;
}

void write_golden(const fs::path& path, const Golden& g, const std::string& body) {
    std::ofstream out(path, std::ios::binary);
    for (const std::string& line : g.header) out << line << '\n';
    out << body;
}

}  // namespace

TEST_CASE("the golden renderer decides on every field of the trace") {
    std::set<std::string_view> keys;
    for (const interpreter::EventField& f : interpreter::event_fields()) {
        INFO(f.key);
        CHECK(kRenderedFields.count(f.key) == 1);
        keys.insert(f.key);
    }
    CHECK(keys.size() == kRenderedFields.size());
}

TEST_CASE("number rendering of the golden traces") {
    CHECK(num(150) == "150");
    CHECK(num(-2.5) == "-2.5");
    CHECK(num(0.25) == "0.25");
    CHECK(num(-0.0001) == "0");
    CHECK(num(1.23456) == "1.235");
    CHECK(num(69.2820323) == "69.282");
}

TEST_CASE("the interpreter's traces of the reference examples match the hand-checked goldens", "[golden][trace]") {
    const fs::path source_dir = KERF_SOURCE_DIR;
    const fs::path golden_dir = source_dir / "tests" / "golden" / "trace";
    const fs::path examples = fs::path(KERF_SHARED_DIR) / "reference" / "examples";
    if (!fs::is_directory(examples)) {
        WARN("no reference examples at " << examples.string() << " (../shared absent): golden trace tests skipped");
        return;
    }
    REQUIRE(fs::is_directory(golden_dir));
    const bool update = std::getenv("KERF_UPDATE_GOLDEN") != nullptr;

    // Skeletons for new examples (KERF_UPDATE_GOLDEN=1 KERF_TRACE_NEW=a.nc,b.nc): the header with
    // the EXPECTED lines and a `# TODO` line that keeps the test failing until it is reviewed.
    if (const char* fresh = std::getenv("KERF_TRACE_NEW"); fresh && update) {
        std::stringstream list(fresh);
        std::string example;
        while (std::getline(list, example, ',')) {
            const fs::path path = golden_dir / (fs::path(example).stem().string() + ".trace");
            const auto dialect = kerf::tests::example_dialect(source_dir, example);
            if (fs::exists(path) || !dialect || !fs::is_regular_file(examples / example)) continue;
            Golden g;
            g.header.push_back("# example: " + example);
            g.header.push_back("# dialect: " + *dialect);
            for (const std::string& e : expected_lines(read_text(examples / example))) g.header.push_back("# " + e);
            g.header.push_back("# TODO: review the trace below and write the # checked: lines");
            write_golden(path, g, "");
        }
    }

    std::vector<fs::path> goldens;
    for (const fs::directory_entry& e : fs::directory_iterator(golden_dir))
        if (e.is_regular_file() && e.path().extension() == ".trace") goldens.push_back(e.path());
    std::sort(goldens.begin(), goldens.end());

    std::size_t checked = 0;
    std::vector<std::string> failed;
    for (const fs::path& path : goldens) {
        const std::string example = path.stem().string() + ".nc";
        INFO("golden " << path.filename().string());
        Golden golden = read_golden(path);
        const auto dialect_id = kerf::tests::example_dialect(source_dir, example);
        const fs::path example_path = examples / example;
        if (!dialect_id || !fs::is_regular_file(example_path)) {
            FAIL_CHECK(example << ": no such reference example (or no dialect for it in tests/golden/ast)");
            failed.push_back(example);
            continue;
        }
        const dialects::Dialect* dialect = dialects::builtin_registry().find(*dialect_id);
        if (!dialect) {
            FAIL_CHECK(example << ": the dialect '" << *dialect_id << "' is not in the built-in registry");
            failed.push_back(example);
            continue;
        }
        const std::string text = read_text(example_path);

        // The header belongs to this example and states what was checked.
        bool header_ok = true;
        auto header_fail = [&](const std::string& why) {
            FAIL_CHECK(example << ": header: " << why);
            header_ok = false;
        };
        if (header_value(golden, "# example: ") != example) header_fail("the first line must be '# example: " + example + "'");
        if (header_value(golden, "# dialect: ") != *dialect_id)
            header_fail("'# dialect: " + *dialect_id + "' expected (tests/example_dialects.hpp)");
        for (const std::string& e : expected_lines(text))
            if (std::find(golden.header.begin(), golden.header.end(), "# " + e) == golden.header.end())
                header_fail("the example's line '" + e + "' is not quoted as '# " + e + "'");
        if (std::none_of(golden.header.begin(), golden.header.end(),
                         [](const std::string& l) { return l.rfind("# checked:", 0) == 0; }))
            header_fail("no '# checked:' line");
        for (const std::string& l : golden.header)
            if (l.rfind("# TODO", 0) == 0) header_fail("not reviewed yet: " + l);

        const Run run = run_example(example, text, *dialect, true);
        const Run strict = run_example(example, text, *dialect, false);
        const std::string actual = render(*dialect, run, strict);
        ++checked;
        // A golden that holds what the reference says while kerf disagrees ("# status: … FAILS …")
        // is never rewritten: fix the code, or change the header after a new review.
        const bool reference_golden = header_value(golden, "# status: ").find("FAILS") != std::string::npos;
        if (update && actual != golden.body && reference_golden)
            WARN(example << ": not rewritten: its golden is the reference's (# status: ... FAILS ...)");
        if (update && actual != golden.body && !reference_golden) {
            write_golden(path, golden, actual);
            WARN(example << ": trace rewritten (KERF_UPDATE_GOLDEN); check it against the # checked: lines");
            continue;
        }
        const std::string diff = line_diff(golden.body, actual);
        if (!diff.empty()) FAIL_CHECK(example << " (dialect " << *dialect_id << ") differs from its golden:\n" << diff);
        if (!diff.empty() || !header_ok) failed.push_back(example);
    }

    std::string list;
    for (const std::string& f : failed) list += "\n  " + f;
    INFO("golden traces checked: " << checked << " of " << goldens.size() << "; failed: " << failed.size() << list);
    CHECK(checked >= 40);
    CHECK(failed.empty());
}
