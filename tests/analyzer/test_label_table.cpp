// analyzer::LabelTable (rule.hpp): the N numbers of a program sorted by number and, within a number,
// by block, whichever way the constructor sorts (a counting sort when the numbers span a small
// range, as CAM output whose N numbers wrap; a merge sort otherwise), and mended by an edit
// (splice + replace, incremental checking) into what building it again gives.
#include <catch2/catch.hpp>

#include <algorithm>
#include <tuple>
#include <vector>

#include "analyzer/rule.hpp"

using kerf::analyzer::LabelTable;

namespace {

std::vector<LabelTable::Entry> wrapped(std::uint32_t blocks, std::int64_t wrap, std::int64_t step) {
    std::vector<LabelTable::Entry> out;
    for (std::uint32_t b = 0; b < blocks; ++b) {
        const std::int64_t n = step * (1 + b % wrap);
        out.push_back({static_cast<double>(n), b});
    }
    return out;
}

bool ordered(const LabelTable& t) {
    const auto e = t.entries();
    for (std::size_t i = 1; i < e.size(); ++i)
        if (e[i - 1].number() > e[i].number() || (e[i - 1].number() == e[i].number() && e[i - 1].block >= e[i].block)) return false;
    return true;
}

std::vector<std::tuple<std::int64_t, double, std::uint32_t>> flat(const LabelTable& t) {
    std::vector<std::tuple<std::int64_t, double, std::uint32_t>> out;
    for (const LabelTable::Entry& e : t.entries()) out.emplace_back(e.number(), e.value, e.block);
    return out;
}

}  // namespace

TEST_CASE("LabelTable sorts by number, then block, with both sorts") {
    // N10..N1000 over and over (a small range: the counting sort).
    const LabelTable small(wrapped(5000, 100, 10));
    CHECK(small.entries().size() == 5000);
    CHECK(ordered(small));
    CHECK(small.count(10) == 50);
    CHECK(small.blocks(10).front() == 0);
    CHECK(small.blocks(10).back() == 4900);
    CHECK(small.count(15) == 0);
    // Numbers far apart (N7, N70000000, ...: the range is too wide for counting): the merge sort.
    const LabelTable wide(wrapped(3000, 30, 7000000));
    CHECK(ordered(wide));
    CHECK(wide.count(7000000) == 100);
    // Ascending already: kept as it is.
    const LabelTable ascending(wrapped(100, 1000, 5));
    CHECK(ordered(ascending));
    // N10.5 is a block of label 10 but not N10 itself.
    const LabelTable fraction({{10.5, 0}, {10.0, 3}, {4.0, 1}});
    CHECK(fraction.count(10) == 2);
    CHECK(fraction.blocks(10) == std::vector<std::uint32_t>{3});
    // The label is the value truncated toward zero (N-10.5 is label -10), as truncated_integer says.
    const LabelTable negative({{-10.5, 0}, {-10.0, 1}, {-11.0, 2}});
    CHECK(negative.count(-10) == 2);
    CHECK(negative.count(-11) == 1);
    CHECK(ordered(negative));
}

TEST_CASE("LabelTable splice and replace give the table of the edited program") {
    std::vector<LabelTable::Entry> before = wrapped(2000, 100, 10);
    LabelTable table(before);
    // Blocks 500..502 (N20, N30, N40) become four blocks numbered N7, N30, none, N9999: later blocks move by one.
    table.splice(500, 503, 1);
    table.replace(500, 504, std::vector<LabelTable::Entry>{{7.0, 500}, {30.0, 501}, {9999.0, 503}});
    std::vector<LabelTable::Entry> after;
    for (const LabelTable::Entry& e : before) {
        if (e.block < 500) after.push_back(e);
        else if (e.block >= 503) after.push_back({e.value, e.block + 1});
    }
    after.push_back({7.0, 500});
    after.push_back({30.0, 501});
    after.push_back({9999.0, 503});
    // The constructor takes the entries in block order.
    std::sort(after.begin(), after.end(), [](const LabelTable::Entry& a, const LabelTable::Entry& b) { return a.block < b.block; });
    CHECK(ordered(table));
    const auto got = flat(table), expected = flat(LabelTable(after));
    REQUIRE(got.size() == expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        INFO(i << ": " << std::get<0>(got[i]) << " " << std::get<2>(got[i]) << " vs " << std::get<0>(expected[i]) << " " << std::get<2>(expected[i]));
        REQUIRE(got[i] == expected[i]);
    }
    CHECK(table.count(7) == 1);
    CHECK(table.count(20) == 19);
    // replace() over a range whose entries are already there (a walk cancelled before) keeps one of each.
    table.replace(500, 504, std::vector<LabelTable::Entry>{{7.0, 500}, {30.0, 501}, {9999.0, 503}});
    CHECK(flat(table) == flat(LabelTable(after)));
}
