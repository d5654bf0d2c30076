// Rule behaviour beyond the one bad/good pair of each fixture: the cases the reference examples
// showed (fragments, cycle parameters that look like other words, dialect-dependent numbers).
#include <catch2/catch.hpp>

#include "tests/analyzer/check_fixture.hpp"

using namespace kerf;
using Findings = std::vector<std::string>;

// K3006: reference/README.md "Example files" — the seeds print excerpts; a fragment is no program.
TEST_CASE("K3006 missing-program-end: programs yes, listing fragments no") {
    const std::string dialect = "fanuc-lathe-a";
    // A program: its O number (dialects.md §3.4) or a '%' tape file makes it one.
    CHECK(test::summary(test::check("O0001\nG00 X0.\n", dialect), "K3006") == Findings{"1:1 warning K3006"});
    CHECK(test::summary(test::check("%\nG00 X0.\nG01 Z-1. F0.2\n%\n", dialect), "K3006") == Findings{"2:1 warning K3006"});
    // A listing with '...' for left-out blocks (001_O001_M316.nc) is a fragment, O number or not.
    CHECK(test::summary(test::check("O0001\nG00 X0.\n...\nG01 Z-1. F0.2\n", dialect), "K3006").empty());
    CHECK(test::summary(test::check("O0001\nN10 G00 X0.\nN110.....\n", dialect), "K3006").empty());
    // No O number and no '%': an excerpt (001_11-5_slow_variant.nc, "fragment without O number").
    CHECK(test::summary(test::check("T0101\nG97 S3500 M4 F0.2\nG0 X0. Z2.\n", dialect), "K3006").empty());
}
