// kerf plot over every reference example and corpus file: the interpreter runs leniently, and each
// picture is a balanced SVG document without NaN or infinity, with a path when the run moved.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"
#include "interpreter/interpreter.hpp"
#include "plot/svg.hpp"
#include "tests/plot/svg_reader.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

std::vector<fs::path> shared_files() {
    std::vector<fs::path> files;
    for (const char* sub : {"reference/examples", "corpus"}) {
        const fs::path dir = fs::path(KERF_SHARED_DIR) / sub;
        if (!fs::is_directory(dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(dir))
            if (e.is_regular_file() && e.path().filename() != "MANIFEST.md") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

bool has_toolpath(const std::string& svg) {
    for (const char* cls : {"<path class=\"rapid\"", "<path class=\"feed\"", "<path class=\"thread\""})
        if (svg.find(cls) != std::string::npos) return true;
    return false;
}

bool moved(const std::vector<interpreter::Event>& events) {
    return std::any_of(events.begin(), events.end(), [](const interpreter::Event& e) {
        return e.kind == interpreter::EventKind::rapid || e.kind == interpreter::EventKind::linear ||
               e.kind == interpreter::EventKind::arc_cw || e.kind == interpreter::EventKind::arc_ccw ||
               e.kind == interpreter::EventKind::thread;
    });
}

}  // namespace

TEST_CASE("kerf plot draws every reference example and corpus file as a well-formed SVG") {
    const std::vector<fs::path> files = shared_files();
    if (files.empty()) {
        WARN("../shared is not there: the plot sweep was not run");
        return;
    }
    std::size_t drawn = 0;
    for (const fs::path& path : files) {
        const std::string text = read(path);
        const dialects::Dialect* d = dialects::builtin_registry().find(grammar::detect_dialect(text).dialect);
        REQUIRE(d);
        interpreter::ProgramSet programs;
        const auto file = programs.add(path.string(), text, *d);
        const auto main = programs.first_program(file);
        if (!main) continue;
        interpreter::Setup setup = interpreter::default_setup(*d);
        setup.step_limit = 200'000;   // M99 at the end of a main program loops until here
        interpreter::VectorSink sink;
        interpreter::RunOptions options;
        options.lenient = true;
        interpreter::run(programs, *main, *d, setup, sink, options);
        // A neutral title: file names could contain "inf".
        const std::string svg = plot::render_svg(sink.events, {d->machine, setup.diameter_x, "sweep"});
        INFO(path.string());
        CHECK(svg.rfind("<svg", 0) == 0);
        CHECK(svg.substr(svg.find_last_not_of(" \n") - 5, 6) == "</svg>");
        CHECK(svg.find("nan") == std::string::npos);
        CHECK(svg.find("inf") == std::string::npos);
        CHECK(test::tags_balanced(svg));
        CHECK(has_toolpath(svg) == moved(sink.events));
        drawn += moved(sink.events);
    }
    // Nearly every program moves; the few that do not are fragments (M codes, settings).
    CHECK(drawn >= files.size() * 3 / 4);
}
