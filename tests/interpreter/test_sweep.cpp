// kerf's interpreter on every reference example and corpus file: it terminates (step limit),
// never crashes, and every event points into the file it came from (issue 3, point 3).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/interpreter/interpreter_fixture.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;

TEST_CASE("the interpreter runs every reference example and corpus file to an end") {
    const std::vector<fs::path> files = test::shared_files_or_warn("the interpreter sweep was not run");
    if (files.empty()) return;
    std::size_t completed = 0;
    for (const fs::path& path : files) {
        const auto run = test::run_shared_file(path);
        if (!run) continue;
        const auto& [d, programs, setup, r, events] = *run;
        INFO(path.string());
        CHECK(r.blocks <= setup.step_limit + 1);
        for (const interpreter::Event& e : events) {
            REQUIRE(e.source.file < programs.file_count());
            REQUIRE(e.source.range.end <= programs.file(e.source.file).text_size());
            REQUIRE(e.source.line >= 1);
            for (const double v : e.end) REQUIRE(std::isfinite(v));
        }
        completed += r.completed;
    }
    // Most examples end cleanly; the rest stop at the alarms their defects deserve.
    CHECK(completed >= files.size() / 4);
}
