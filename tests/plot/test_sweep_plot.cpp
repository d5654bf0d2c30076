// kerf plot over every reference example and corpus file: the interpreter runs leniently, and each
// picture is a balanced SVG document without NaN or infinity, with a path when the run moved.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "plot/svg.hpp"
#include "tests/interpreter/interpreter_fixture.hpp"
#include "tests/plot/svg_reader.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

bool has_toolpath(const std::string& svg) {
    for (const char* cls : {"<path class=\"rapid\"", "<path class=\"feed\"", "<path class=\"thread\""})
        if (svg.find(cls) != std::string::npos) return true;
    return false;
}

bool moved(const std::vector<interpreter::Event>& events) {
    return std::any_of(events.begin(), events.end(), [](const interpreter::Event& e) {
        return test::is_move(e.kind) || e.kind == interpreter::EventKind::thread;
    });
}

}  // namespace

TEST_CASE("kerf plot draws every reference example and corpus file as a well-formed SVG") {
    const std::vector<fs::path> files = test::shared_files_or_warn("the plot sweep was not run");
    if (files.empty()) return;
    interpreter::RunOptions options;
    options.lenient = true;
    std::size_t drawn = 0;
    for (const fs::path& path : files) {
        const auto run = test::run_shared_file(path, options);
        if (!run) continue;
        const auto& [d, programs, setup, r, events] = *run;
        // A neutral title: file names could contain "inf".
        const std::string svg = plot::render_svg(events, {d->machine, setup.diameter_x, "sweep", plot::Frame::part});
        INFO(path.string());
        CHECK(svg.rfind("<svg", 0) == 0);
        CHECK(svg.substr(svg.find_last_not_of(" \n") - 5, 6) == "</svg>");
        CHECK(svg.find("nan") == std::string::npos);
        CHECK(svg.find("inf") == std::string::npos);
        CHECK(test::tags_balanced(svg));
        CHECK(has_toolpath(svg) == moved(events));
        drawn += moved(events);
    }
    // Nearly every program moves; the few that do not are fragments (M codes, settings).
    CHECK(drawn >= files.size() * 3 / 4);
}
