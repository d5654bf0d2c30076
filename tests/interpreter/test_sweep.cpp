// kerf's interpreter on every reference example and corpus file: it terminates (step limit),
// never crashes, and every event points into the file it came from (issue 3, point 3).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"
#include "interpreter/interpreter.hpp"

namespace fs = std::filesystem;
using namespace kerf;

TEST_CASE("the interpreter runs every reference example and corpus file to an end") {
    std::vector<fs::path> files;
    for (const char* sub : {"reference/examples", "corpus"}) {
        const fs::path dir = fs::path(KERF_SHARED_DIR) / sub;
        if (!fs::is_directory(dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(dir))
            if (e.is_regular_file() && e.path().filename() != "MANIFEST.md") files.push_back(e.path());
    }
    if (files.empty()) {
        WARN("../shared is not there: the interpreter sweep was not run");
        return;
    }
    std::sort(files.begin(), files.end());
    std::size_t completed = 0;
    for (const fs::path& path : files) {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        const std::string text = ss.str();
        const dialects::Dialect* d = dialects::builtin_registry().find(grammar::detect_dialect(text).dialect);
        REQUIRE(d);
        interpreter::ProgramSet programs;
        const auto file = programs.add(path.string(), text, *d);
        const auto main = programs.first_program(file);
        if (!main) continue;
        interpreter::Setup setup = interpreter::default_setup(*d);
        setup.step_limit = 200'000;   // M99 at the end of a main program loops until here
        interpreter::VectorSink sink;
        const interpreter::RunResult r = interpreter::run(programs, *main, *d, setup, sink);
        INFO(path.string());
        CHECK(r.blocks <= setup.step_limit + 1);
        for (const interpreter::Event& e : sink.events) {
            REQUIRE(e.source.file < programs.file_count());
            REQUIRE(e.source.range.end <= programs.file(e.source.file).tree.text.size());
            REQUIRE(e.source.line >= 1);
            for (const double v : e.end) REQUIRE(std::isfinite(v));
        }
        completed += r.completed;
    }
    // Most examples end cleanly; the rest stop at the alarms their defects deserve.
    CHECK(completed >= files.size() / 4);
}
