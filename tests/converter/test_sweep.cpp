// Every reference example and corpus file converted (issue 16, points 2 and 3):
//   - a program of a lathe G-code system (fanuc-lathe-a/b/c, spinner-lathe-a/b/c) to the other two:
//     the result dry-runs to the same motion as the source (kind, end, centre, feed and feed mode,
//     dwell, machine position, alarms; 0.001 mm), A → B → C → A gives the original motion, and
//     every comment and N number is still there; A → B → A gives the original text byte for byte;
//   - a mill program to every other mill control, on one machine description (the source's
//     built-in machine, each side in its dialect's reading, so the offsets are shared): the same.
// A conversion that reports a construct it left as it is (exit 1 of `kerf convert`) is not held to
// the same motion: the report is the answer. The counts of clean conversions are pinned below so
// that a regression that turns conversions into reports does not pass silently.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>

#include "grammar/detect.hpp"
#include "tests/converter/convert_fixture.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

bool left_something(const test::Converted& c) {
    return std::any_of(c.reports.begin(), c.reports.end(),
                       [](const converter::Report& r) { return r.kind == converter::ReportKind::unconverted; });
}

std::string what(const std::optional<interpreter::TraceDifference>& d) {
    return d ? d->what + " (input line " + std::to_string(d->input_line) + ", output line " + std::to_string(d->output_line) + ")"
             : std::string();
}

// The lathe system of a dialect id and the ids of its three systems ("spinner-lathe-", "fanuc-lathe-").
std::optional<std::string> lathe_family(const std::string& id) {
    for (const char* family : {"fanuc-lathe-", "spinner-lathe-"})
        if (id.rfind(family, 0) == 0 && id.size() == std::string(family).size() + 1) return std::string(family);
    return std::nullopt;
}

struct Tally {
    std::size_t conversions = 0, clean = 0, verified = 0, round_trips = 0;
};

// One conversion: comments and N numbers kept; unless a construct was left as it is, the same
// motion. Returns the converted text when it was verified.
std::optional<std::string> check_conversion(const std::string& text, const dialects::Dialect& from, const dialects::Dialect& to,
                                            const std::vector<std::string>& marks, Tally& tally) {
    INFO("to " << to.id);
    const test::Converted out = test::convert_text(text, from, to);
    ++tally.conversions;
    tally.clean += out.clean;
    CHECK(test::comments_and_numbers(out.text, to) == marks);
    if (left_something(out)) return std::nullopt;
    const auto difference = test::motion_difference(text, from, out.text, to);
    INFO(what(difference));
    CHECK_FALSE(difference.has_value());
    if (difference) return std::nullopt;
    ++tally.verified;
    return out.text;
}

}  // namespace

TEST_CASE("lathe systems: every example and corpus program to the other two systems and back") {
    const auto files = test::shared_files_or_warn("the converter's lathe sweep was not run");
    if (files.empty()) return;
    Tally tally;
    for (const fs::path& path : files) {
        const std::string text = test::read_text(path);
        const std::string id = grammar::detect_dialect(text).dialect;
        const auto family = lathe_family(id);
        if (!family) continue;
        INFO(path.filename().string() << " (" << id << ")");
        const dialects::Dialect& from = test::dialect(id);
        const std::vector<std::string> marks = test::comments_and_numbers(text, from);
        for (const char system : {'a', 'b', 'c'}) {
            const dialects::Dialect& to = test::dialect(*family + system);
            if (to.id == from.id) continue;
            const std::optional<std::string> out = check_conversion(text, from, to, marks, tally);
            if (!out) continue;
            // Back to where it came from: the same text (issue 16, point 3).
            const test::Converted back = test::convert_text(*out, to, from);
            CHECK(back.text == text);
            tally.round_trips += back.text == text;
        }
        // A → B → C → A (or from wherever the file starts, round the three systems): the same motion.
        const std::string& s = from.id;
        const char first = s.back();
        const char second = first == 'a' ? 'b' : first == 'b' ? 'c' : 'a';
        const char third = second == 'a' ? 'b' : second == 'b' ? 'c' : 'a';
        const test::Converted one = test::convert_text(text, from, test::dialect(*family + second));
        const test::Converted two = test::convert_text(one.text, test::dialect(*family + second), test::dialect(*family + third));
        const test::Converted three = test::convert_text(two.text, test::dialect(*family + third), from);
        CHECK(test::comments_and_numbers(three.text, from) == marks);
        if (left_something(one) || left_something(two) || left_something(three)) continue;
        const auto difference = test::motion_difference(text, from, three.text, from);
        INFO("round the three systems: " << what(difference));
        CHECK_FALSE(difference.has_value());
    }
    WARN(tally.conversions << " conversions, " << tally.clean << " clean, " << tally.verified << " verified, "
                           << tally.round_trips << " round trips byte for byte");
    // 70 lathe programs (the SPINNER and seed-003 examples, the lathe corpus), two targets each.
    CHECK(tally.conversions >= 120);
    CHECK(tally.verified >= 110);
    CHECK(tally.round_trips == tally.verified);
}

TEST_CASE("mill controls: every mill example to every other mill control") {
    const auto files = test::shared_files_or_warn("the converter's mill sweep was not run");
    if (files.empty()) return;
    const char* mills[] = {"fanuc-mill", "adv400-mill", "pcnc-mill", "iso-legacy-mill"};
    Tally tally;
    for (const fs::path& path : files) {
        if (path.parent_path().filename() != "examples") continue;
        const std::string text = test::read_text(path);
        const std::string id = grammar::detect_dialect(text).dialect;
        if (std::find(std::begin(mills), std::end(mills), id) == std::end(mills)) continue;
        INFO(path.filename().string() << " (" << id << ")");
        const dialects::Dialect& from = test::dialect(id);
        const std::vector<std::string> marks = test::comments_and_numbers(text, from);
        for (const char* target : mills) {
            if (id != target) check_conversion(text, from, test::dialect(target), marks, tally);
        }
    }
    WARN(tally.conversions << " conversions, " << tally.clean << " clean, " << tally.verified << " verified");
    CHECK(tally.conversions == 72);   // 24 mill examples, three other controls each
    CHECK(tally.verified >= 25);
}
