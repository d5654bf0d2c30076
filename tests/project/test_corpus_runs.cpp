// issue 12, "what must be shown" 2: how the dry run of every corpus file ends, as `kerf run --lenient
// FILE` runs it (project layer: detected dialect, built-in machine, subprograms through the program
// index of the file's folder), against tests/golden/run/corpus-expected.txt, where each ending was
// reviewed against the file with its reason. A file missing from the list, or listed and gone,
// fails too: the list is the whole corpus.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "interpreter/sink.hpp"
#include "project/dry_run.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

const fs::path kCorpus = fs::path(KERF_SHARED_DIR) / "corpus";

// "path: ending" lines; '#' starts a comment (the reason, on the lines before).
std::map<std::string, std::string> read_expected() {
    std::map<std::string, std::string> out;
    std::istringstream in(test::read_text(fs::path(KERF_SOURCE_DIR) / "tests/golden/run/corpus-expected.txt"));
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t colon = line.find(": ");
        REQUIRE(colon != std::string::npos);
        out[line.substr(0, colon)] = line.substr(colon + 2);
    }
    return out;
}

class NullSink : public interpreter::EventSink {
public:
    void on_event(const interpreter::Event&) override {}
};

// "normal", "repeats" (a bar-feed M99 loop, one pass), "alarm N at LINE" (the first alarm), or
// "no program" / "unusable".
std::string ending_of(const fs::path& file) {
    project::Overrides overrides;
    overrides.limits.time_limit_s = 0.0;   // deterministic: the step and move limits only
    auto workspace = std::make_shared<project::Workspace>(std::make_shared<project::DiskFileSystem>(), overrides);
    project::PreparedRun prepared = project::prepare_dry_run(workspace, file);
    if (prepared.outcome == project::PreparedRun::Outcome::no_program) return "no program";
    if (prepared.outcome != project::PreparedRun::Outcome::ready) return "unusable";
    project::DryRun& run = *prepared.run;
    NullSink sink;
    const interpreter::RunResult r = project::execute(run, sink, true);
    if (!r.alarms.empty()) {
        const interpreter::Event& a = r.alarms.front();
        const std::string where = a.source.file == run.main.file ? "" : fs::path(run.programs.file(a.source.file).name()).filename().string() + ":";
        return fmt::format("alarm {} at {}{}", a.code, where, a.source.line);
    }
    if (r.repeats) return "repeats";
    return r.completed ? "normal" : "incomplete";
}

}  // namespace

TEST_CASE("every corpus file's dry run ends as reviewed in tests/golden/run/corpus-expected.txt", "[corpus][run]") {
    if (!fs::is_directory(kCorpus)) {
        WARN("../shared/corpus is not there: skipped");
        return;
    }
    std::map<std::string, std::string> expected = read_expected();
    std::size_t files = 0;
    for (const auto& e : fs::recursive_directory_iterator(kCorpus)) {
        if (!e.is_regular_file() || e.path().filename() == "MANIFEST.md") continue;
        ++files;
        const std::string name = fs::relative(e.path(), kCorpus).generic_string();
        INFO(name);
        const auto it = expected.find(name);
        const std::string ending = ending_of(e.path());
        if (it == expected.end()) {
            FAIL_CHECK("not in corpus-expected.txt; it ends: " << ending);
            continue;
        }
        CHECK(ending == it->second);
        expected.erase(it);
    }
    CHECK(files == 60);
    for (const auto& [name, ending] : expected) FAIL_CHECK(name << ": listed, but no such corpus file");
}
