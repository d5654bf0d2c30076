// Incremental static checking (analyzer/incremental.hpp) behind the server's diagnostics: after
// every edit of the document store (lsp/document.hpp, its edit log) the findings are exactly those
// of check_static on the whole new text, finished alike. On every reference example and corpus file
// under its detected dialect, with random edits (tests/lsp/random_edits.hpp) and keystrokes that
// change no fact (a digit typed into a number, a character deleted); and on hand-made cases that show
// the walk stays short where it may and goes whole where it must.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <random>
#include <string>

#include "analyzer/analyze.hpp"
#include "analyzer/incremental.hpp"
#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"
#include "lsp/document.hpp"
#include "tests/lsp/random_edits.hpp"
#include "tests/shared_files.hpp"

using namespace kerf;

namespace {

std::shared_ptr<const lsp::FileSettings> settings_for(const std::string& dialect) {
    auto s = std::make_shared<lsp::FileSettings>();
    s->registry = std::shared_ptr<const dialects::Registry>(&dialects::builtin_registry(), [](const dialects::Registry*) {});
    s->dialect = s->registry->find(dialect);
    REQUIRE(s->dialect != nullptr);
    s->setup = interpreter::default_setup(*s->dialect);
    return s;
}

// Findings as text, everything a client sees of them.
std::vector<std::string> shown(std::vector<analyzer::Finding> findings, const lsp::Document& doc) {
    analyzer::finish_findings(findings, doc.tree(), doc.lines(), {});
    std::vector<std::string> out;
    for (const analyzer::Finding& f : findings) {
        std::string s = fmt::format("{} [{},{}) {} | {}", f.rule, f.range.begin, f.range.end, f.message, f.hint);
        for (const analyzer::Related& r : f.related) s += fmt::format(" | related [{},{}) {}", r.range.begin, r.range.end, r.message);
        if (f.fix)
            for (const analyzer::TextEdit& e : f.fix->edits) s += fmt::format(" | fix [{},{}) '{}'", e.range.begin, e.range.end, e.replacement);
        out.push_back(std::move(s));
    }
    return out;
}

// A document and its incremental check, as the analysis worker keeps them.
struct Checked {
    std::shared_ptr<const lsp::Document> doc;
    analyzer::IncrementalStatic check{64};   // a checkpoint every 64 blocks: the examples are short
    std::uint64_t serial = 0;
    const analyzer::CheckOptions* options = nullptr;   // none: the defaults
    bool shares = false;                               // the static rules in two shares, as the server walks them
    analyzer::IncrementalStatic second{64};

    // The incremental findings, and check_static's on the same version.
    std::pair<std::vector<std::string>, std::vector<std::string>> both(const std::atomic<bool>* cancel = nullptr) {
        // The store's line index, moved by the edits (ast::LineIndex::edit), is that of the text.
        const ast::LineIndex fresh(doc->text());
        REQUIRE(doc->lines().line_count() == fresh.line_count());
        for (std::uint32_t line = 0; line < fresh.line_count(); ++line) REQUIRE(doc->lines().line_start(line) == fresh.line_start(line));
        interpreter::ProgramSet programs;
        const std::uint32_t file = programs.add_parsed(doc->path().string(), doc, doc->typed(), doc->lines());
        const lsp::FileSettings& s = doc->settings();
        const analyzer::CheckOptions defaults;
        const analyzer::CheckOptions& o = options ? *options : defaults;
        analyzer::IncrementalStatic::Input in{programs, file, *s.dialect, s.setup, o, {}, 0, doc->edits_since(serial), cancel};
        if (shares) in.shards = 2;
        std::optional<std::vector<analyzer::Finding>> got = check.check(in);
        if (shares) {
            analyzer::IncrementalStatic::Input other = in;
            other.shard = 1;
            std::optional<std::vector<analyzer::Finding>> more = second.check(other);
            if (got && more) got->insert(got->end(), more->begin(), more->end());
            if (!more) got.reset();
        }
        serial = doc->serial();
        if (!got) return {};
        return {shown(std::move(*got), *doc), shown(analyzer::check_static(programs, file, *s.dialect, s.setup, o), *doc)};
    }
    void edit(std::uint32_t begin, std::uint32_t end, const std::string& text) {
        std::vector<std::string> problems;
        const lsp::ContentChange c{std::make_pair(doc->position(begin), doc->position(end)), text};
        doc = lsp::Document::edit(std::move(doc), doc->version() + 1, {c}, problems);
        REQUIRE(problems.empty());
    }
};

// A keystroke that changes no fact: a digit typed after a digit, or a blank or digit deleted.
bool keystroke(Checked& c, std::mt19937& rng) {
    const std::string& text = c.doc->text();
    if (text.empty()) return false;
    for (int tries = 0; tries < 20; ++tries) {
        const auto at = static_cast<std::uint32_t>(rng() % text.size());
        const char ch = text[at];
        if (ch < '0' || ch > '9') continue;
        if (rng() % 2) c.edit(at + 1, at + 1, std::string(1, static_cast<char>('0' + rng() % 10)));
        else c.edit(at, at + 1, "");
        return true;
    }
    return false;
}

analyzer::IncrementalStatic::Input input(Checked& c, interpreter::ProgramSet& programs, std::uint32_t file, const analyzer::CheckOptions& options) {
    const lsp::FileSettings& s = c.doc->settings();
    return {programs, file, *s.dialect, s.setup, options, {}, 0, c.doc->edits_since(c.serial), nullptr};
}

// Line 5 + i is "N<10 + i> G01 X<i % 90>.5 Y2. F100.", then `before_end`, M30 and '%'.
std::string numbered_program(int lines, const std::string& before_end = {}) {
    std::string text = "%\nO1000 (LONG)\nG21 G17 G90\nT1 M06\nG43 H1 Z50.\n";
    for (int i = 0; i < lines; ++i) text += fmt::format("N{} G01 X{}.5 Y2. F100.\n", 10 + i, i % 90);
    return text + before_end + "M30\n%\n";
}

}  // namespace

TEST_CASE("incremental static check equals check_static after every edit, on every example and corpus file") {
    // Both ways the server may walk: all static rules in one walk, or in two shares (two threads).
    const bool shares = GENERATE(false, true);
    std::size_t files = 0, edits = 0, partial = 0;
    for (const auto& path : test::shared_files_or_warn("no incremental check sweep")) {
        const std::string text = test::read_text(path);
        if (text.find('\0') != std::string::npos) continue;   // the server does not parse binary files
        INFO(path.filename().string() << (shares ? " (two shares)" : ""));
        Checked c;
        c.shares = shares;
        c.doc = lsp::Document::open("file:///t.nc", "/t.nc", 1, text, settings_for(grammar::detect_dialect(text).dialect));
        auto [got, expected] = c.both();
        REQUIRE(got == expected);
        std::mt19937 rng(static_cast<std::uint32_t>(text.size()));
        for (int i = 0; i < 16; ++i) {
            if (i % 4 == 3) {
                std::string storage;
                const lsp::ByteEdit e = test::random_edit(c.doc->text(), rng, storage);
                c.edit(e.begin, e.end, std::string(e.text));
            } else if (!keystroke(c, rng)) {
                continue;
            }
            INFO("edit " << i);
            std::tie(got, expected) = c.both();
            REQUIRE(got == expected);
            partial += !c.check.walked_whole();
            ++edits;
        }
        ++files;
    }
    if (files) {
        CHECK(edits > files * 12);
        CHECK(partial > edits / 2);   // most keystrokes were checked without a whole walk
    }
}

TEST_CASE("incremental static check: a keystroke walks a few blocks; a changed fact walks the file whole") {
    Checked c;
    c.doc = lsp::Document::open("file:///t.nc", "/t.nc", 1, numbered_program(5000, "GOTO 2000\n"), settings_for("fanuc-mill"));
    auto [got, expected] = c.both();
    REQUIRE(got == expected);
    CHECK(c.check.walked_whole());
    const auto line = [&](int n) { return static_cast<std::uint32_t>(c.doc->lines().line_start(static_cast<std::uint32_t>(n))); };
    const auto x_digit = [&](int n) { return static_cast<std::uint32_t>(c.doc->text().find('X', line(n)) + 1); };
    // Line 2504, "N2509 G01 X69.5 Y2. F100.": X69.5 → X9.5. The walk resumes at the checkpoint
    // before (every 64 blocks) and stops at the first one after whose state is the last walk's.
    c.edit(x_digit(2504), x_digit(2504) + 1, "");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
    CHECK(c.check.walked_blocks() <= 2 * 64 + 1);
    // Line 3000, "N3005 G01 ...": G01 → G00 changes the modal state for the blocks after it until
    // the next G01, which is the next block: the walk still ends at the next checkpoint.
    c.edit(line(3000) + 7, line(3000) + 9, "00");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK(c.check.walked_blocks() <= 2 * 64 + 1);
    // A label nothing jumps to and no other block carries: renumbering it matters to no rule.
    c.edit(line(2995), line(2995) + 5, "N7001");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
    // The number of the next block (N3001): K3011 sums up every label of the program from the kept
    // label table (a program check), so the walk stays short and the finding says N3001 is on two
    // blocks; numbering it back takes the finding away.
    const auto k3011 = [&] { return std::count_if(got.begin(), got.end(), [](const std::string& f) { return f.starts_with("K3011"); }); };
    c.edit(line(2995), line(2995) + 5, "N3001");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
    CHECK(c.check.walked_blocks() <= 2 * 64 + 1);
    CHECK(k3011() == 1);
    c.edit(line(2995), line(2995) + 5, "N3000");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
    CHECK(k3011() == 0);
    // Line 1995 holds N2000, the GOTO's target: renumbering it changes what the label rules say
    // (K3001 now fires at the GOTO), so the file is walked whole.
    CHECK(std::count_if(got.begin(), got.end(), [](const std::string& f) { return f.starts_with("K3001"); }) == 0);
    c.edit(line(1995), line(1995) + 5, "N2001");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK(c.check.walked_whole());
    CHECK(std::count_if(got.begin(), got.end(), [](const std::string& f) { return f.starts_with("K3001"); }) == 1);
    // Several edits between two checks are taken in order.
    c.edit(x_digit(100), x_digit(100), "7");
    c.edit(x_digit(4000), x_digit(4000) + 1, "");
    c.edit(x_digit(100) + 1, x_digit(100) + 1, "5");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
}

TEST_CASE("incremental static check: CAM output whose N numbers wrap keeps short walks when labels change") {
    // Every N number is on 50 blocks (N10..N1000 over and over): K3011's one finding names the first
    // ten numbers and counts the rest. Edits that add, remove, renumber and duplicate labels change
    // that finding without a whole walk (the label table is kept and mended: LabelTable::replace).
    std::string text = "%\nO2000 (WRAP)\nG21 G17 G90\nT1 M06\nG43 H1 Z50.\n";
    for (int i = 0; i < 5000; ++i) text += fmt::format("N{} G01 X{}.5 Y2. F100.\n", 10 + 10 * (i % 100), i % 90);
    text += "M30\n%\n";
    Checked c;
    c.doc = lsp::Document::open("file:///t.nc", "/t.nc", 1, text, settings_for("fanuc-mill"));
    auto [got, expected] = c.both();
    REQUIRE(got == expected);
    const auto line = [&](int n) { return static_cast<std::uint32_t>(c.doc->lines().line_start(static_cast<std::uint32_t>(n))); };
    const auto k3011 = [&] {
        const auto it = std::find_if(got.begin(), got.end(), [](const std::string& f) { return f.starts_with("K3011"); });
        return it == got.end() ? std::string() : *it;
    };
    REQUIRE(k3011().find("and 90 more numbers") != std::string::npos);
    // N10 → N7 on the first block: N7 is on one block; the numbers now first repeat from N20.
    c.edit(line(5), line(5) + 3, "N7");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
    CHECK(k3011().find("N20, N30") != std::string::npos);
    // A new number on a late block (N5 on line 4000), then the same number on an early one: N5 repeats.
    c.edit(line(4000), line(4000) + 4, "N5");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
    c.edit(line(100), line(100) + 4, "N5");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
    // Several label edits between two checks, one of them a line deleted.
    c.edit(line(2000), line(2000) + 4, "N9");
    c.edit(line(3000), line(3001), "");
    c.edit(line(10), line(10) + 4, "N9");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
}

TEST_CASE("incremental static check honours resident programs and callers' arguments as check_static does") {
    // The server passes .kerf.toml [programs] resident and the index's caller arguments: the
    // incremental walk must see them too (it did not: K3003 on resident calls, K4001 on arguments).
    analyzer::CheckOptions options;
    options.resident = [](std::int64_t n) { return n >= 9000 && n <= 9999; };
    options.caller_arguments = [](std::int64_t n) { return n == 1 ? std::vector<int>{1, 2} : std::vector<int>{}; };
    const std::string text = "%\nO0001\n#100=#1+#2\nM98 P9810\nM98 P8000\nM99\n%\n";
    Checked c;
    c.options = &options;
    c.doc = lsp::Document::open("file:///t.nc", "/t.nc", 1, text, settings_for("fanuc-mill"));
    auto [got, expected] = c.both();
    CHECK(got == expected);
    const auto count = [&](std::string_view rule) {
        return std::count_if(got.begin(), got.end(), [&](const std::string& f) { return f.starts_with(rule); });
    };
    CHECK(count("K3003") == 1);   // P8000 is not resident, P9810 is
    CHECK(count("K4001") == 0);   // #1 and #2 are arguments of O0001's callers
}

TEST_CASE("incremental static check: states that differ go on to the program's end, findings pointing into an edit start over") {
    Checked c;
    // A loop open across the edit: Loops keeps the DO token, written relative to the checkpoint, so
    // an edit that adds a token between them makes the states differ up to the end.
    std::string text = "O1\n#1=0\nWHILE [#1 LT 2] DO 1\n";
    for (int i = 0; i < 400; ++i) text += fmt::format("G01 X{}. F100.\n", i);
    text += "#1=#1+1\n";   // no END 1: K3004 at the DO, reported when the program ends
    text += "M30\n";
    c.doc = lsp::Document::open("file:///t.nc", "/t.nc", 1, text, settings_for("fanuc-mill"));
    c.both();
    const auto line = [&](int n) { return static_cast<std::uint32_t>(c.doc->lines().line_start(static_cast<std::uint32_t>(n))); };
    c.edit(line(200), line(200), "G01 ");   // one more word (the G01 again: no fact, no finding)
    auto [got, expected] = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
    CHECK(c.check.walked_blocks() > 150);   // from the checkpoint before line 200 to the end
    CHECK(std::count_if(got.begin(), got.end(), [](const std::string& f) { return f.starts_with("K3004"); }) == 1);

    // K3002's related information names the blocks of an ambiguous label: an edit inside one of
    // them moves the range a kept finding points at, so the file is walked whole.
    Checked d;
    std::string twice = "O2\nN10 G00 X0.\nGOTO 10\n";
    for (int i = 0; i < 300; ++i) twice += fmt::format("G01 X{}. F100.\n", i);
    twice += "N10 X1.\nM30\n";
    d.doc = lsp::Document::open("file:///u.nc", "/u.nc", 1, twice, settings_for("fanuc-mill"));
    d.both();
    const std::uint32_t last_n10 = static_cast<std::uint32_t>(d.doc->text().rfind("N10 X1.") + 5);
    d.edit(last_n10, last_n10, "5");   // N10 X15.
    std::tie(got, expected) = d.both();
    CHECK(got == expected);
    CHECK(d.check.walked_whole());
}

TEST_CASE("incremental static check: a cancelled walk is finished by the next check") {
    // A loop open across the edit makes the walk go on to the end: long enough to be cancelled
    // (the walk looks at the flag every 4096 blocks).
    std::string text = "O1\n#1=0\nWHILE [#1 LT 2] DO 1\n";
    for (int i = 0; i < 20000; ++i) text += fmt::format("G01 X{}. F100.\n", i % 100);
    text += "#1=#1+1\nM30\n";
    std::atomic<bool> cancel{true};
    const auto cancelled = [&](Checked& c) {
        interpreter::ProgramSet programs;
        const std::uint32_t file = programs.add_parsed(c.doc->path().string(), c.doc, c.doc->typed(), c.doc->lines());
        const analyzer::CheckOptions options;
        analyzer::IncrementalStatic::Input in = input(c, programs, file, options);
        in.cancel = &cancel;
        const bool stopped = !c.check.check(in).has_value();
        c.serial = c.doc->serial();
        return stopped;
    };
    Checked c;
    c.doc = lsp::Document::open("file:///t.nc", "/t.nc", 1, text, settings_for("fanuc-mill"));
    CHECK(cancelled(c));   // the first, whole walk
    auto [got, expected] = c.both();
    CHECK(got == expected);
    CHECK(c.check.walked_whole());
    const auto line = [&](int n) { return static_cast<std::uint32_t>(c.doc->lines().line_start(static_cast<std::uint32_t>(n))); };
    c.edit(line(100), line(100), "G01 ");
    CHECK(cancelled(c));   // a partial walk stopped: what it had to walk is kept for the next
    c.edit(line(15000) + 5, line(15000) + 5, "3");
    std::tie(got, expected) = c.both();
    CHECK(got == expected);
    CHECK_FALSE(c.check.walked_whole());
    CHECK(c.check.walked_blocks() > 19000);   // from before line 100 to the end
}
