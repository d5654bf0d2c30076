// Round trip over every reference example and every corpus file (issue: foundation, point 2):
// `kerf parse --print` gives back the input byte for byte, and the library does so under every
// dialect's lexical rules, with every byte in a token or trivia. Skips with a message when
// ../shared is absent.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ast/printer.hpp"
#include "ast/typed.hpp"
#include "grammar/parse.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> shared_files() {
    std::vector<fs::path> out;
    for (const char* sub : {"/reference/examples", "/corpus"}) {
        const fs::path dir = fs::path(KERF_SHARED_DIR) / (sub + 1);
        if (!fs::is_directory(dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(dir))
            if (e.is_regular_file() && e.path().filename() != "MANIFEST.md") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string run_print(const fs::path& p) {
    const std::string cmd = std::string(KERF_BINARY) + " parse --print '" + p.string() + "' 2>/dev/null";
    FILE* pipe = popen(cmd.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::string out;
    char buf[65536];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
    pclose(pipe);
    return out;
}

}  // namespace

TEST_CASE("reference examples and corpus: lossless under every dialect") {
    const auto files = shared_files();
    if (files.empty()) {
        WARN("../shared is not there: round-trip checks over the reference and corpus were not run");
        return;
    }
    REQUIRE(files.size() >= 140);   // 88 examples + 60 corpus files
    const auto& registry = kerf::dialects::builtin_registry();
    std::size_t parses = 0;
    for (const fs::path& file : files) {
        const std::string text = read(file);
        for (const std::string& id : registry.ids()) {
            const kerf::dialects::Dialect* d = registry.find(id);
            kerf::ast::SyntaxTree tree = kerf::grammar::parse(text, d->lexical);
            (void)kerf::ast::TypedFile::bind(tree, *d);
            INFO(file.string() << " as " << id);
            REQUIRE(kerf::ast::print(tree) == text);
            const auto violation = kerf::ast::check_lossless(tree);
            INFO((violation ? violation->what : std::string()));
            REQUIRE_FALSE(violation.has_value());
            ++parses;
        }
    }
    CHECK(parses == files.size() * registry.ids().size());
}

TEST_CASE("reference examples and corpus: kerf parse --print is byte for byte") {
    const auto files = shared_files();
    if (files.empty()) {
        WARN("../shared is not there: round-trip checks over the reference and corpus were not run");
        return;
    }
    for (const fs::path& file : files) {
        INFO(file.string());
        REQUIRE(run_print(file) == read(file));
    }
}
