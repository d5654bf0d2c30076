// Runs the built kerf binary: `kerf dialects` and `kerf explain`.
#include "tests/cli/cli_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using kerf::test::shell_quote;

namespace {

struct Run {
    int exit_code = -1;
    std::string out;   // stdout and stderr together
};

// stdin is the test's own (not /dev/null as kerf::test::run_kerf has it).
Run kerf_cli(const std::string& args) {
    const kerf::test::Captured c = kerf::test::capture(shell_quote(KERF_BINARY) + " " + args + " 2>&1");
    REQUIRE(c.status != -1);
    REQUIRE(WIFEXITED(c.status));
    return {WEXITSTATUS(c.status), c.out};
}

bool has_cyrillic(const std::string& s) {
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        const auto a = static_cast<unsigned char>(s[i]), b = static_cast<unsigned char>(s[i + 1]);
        if ((a == 0xD0 || a == 0xD1) && b >= 0x80 && b <= 0xBF) return true;
    }
    return false;
}

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

}  // namespace

TEST_CASE("the kerf binary exists") {
    INFO(KERF_BINARY);
    REQUIRE(fs::exists(KERF_BINARY));
}

TEST_CASE("kerf dialects lists the 11 built-in dialects") {
    const Run r = kerf_cli("dialects");
    INFO(r.out);
    CHECK(r.exit_code == 0);
    for (const char* id : {"fanuc-lathe-a", "fanuc-lathe-b", "fanuc-lathe-c", "spinner-lathe-a", "spinner-lathe-b",
                           "spinner-lathe-c", "fanuc-mill", "adv400-mill", "adv400-lathe", "pcnc-mill",
                           "iso-legacy-mill"}) {
        INFO(id);
        CHECK(contains(r.out, id));
    }
}

TEST_CASE("kerf explain") {
    SECTION("G71 in system A, in Russian, shows the group") {
        const Run r = kerf_cli("explain G71 --dialect fanuc-lathe-a --lang ru");
        INFO(r.out);
        CHECK(r.exit_code == 0);
        CHECK(contains(r.out, "G71"));
        CHECK(has_cyrillic(r.out));
        CHECK(contains(r.out, "группа: 00"));
        CHECK(contains(r.out, "rough-turning-cycle"));
    }
    SECTION("G71 in system C is metric input") {
        const Run r = kerf_cli("explain G71 --dialect fanuc-lathe-c");
        INFO(r.out);
        CHECK(r.exit_code == 0);
        CHECK(contains(r.out, "Metric input"));
        CHECK(contains(r.out, "group: 06"));
        CHECK_FALSE(contains(r.out, "rough"));
    }
    SECTION("an unknown code exits 1") {
        const Run r = kerf_cli("explain G999 --dialect fanuc-mill");
        INFO(r.out);
        CHECK(r.exit_code == 1);
        CHECK(contains(r.out, "G999"));
    }
    SECTION("K9999 is not a rule (issue 12: it said 'not a code of fanuc-lathe-a')") {
        const Run r = kerf_cli("explain K9999");
        INFO(r.out);
        CHECK(r.exit_code == 1);
        CHECK(contains(r.out, "K9999 is not a rule of kerf check"));
        CHECK_FALSE(contains(r.out, "fanuc-lathe-a"));
    }
    SECTION("G81 without --dialect shows the dialects that have it (the mills; no lathe system has G81)") {
        const Run r = kerf_cli("explain G81");
        INFO(r.out);
        CHECK(r.exit_code == 0);
        CHECK(contains(r.out, "fanuc-mill"));
        CHECK_FALSE(contains(r.out, "fanuc-lathe-a"));
    }
    SECTION("a parser diagnostic id names its rule") {
        const Run r = kerf_cli("explain S0103");
        INFO(r.out);
        CHECK(r.exit_code == 0);
        CHECK(contains(r.out, "S0103 is reported by kerf check as K1003"));
        CHECK(contains(r.out, "letter-o-for-zero"));
    }
    SECTION("an unknown dialect exits 2") {
        const Run r = kerf_cli("explain G71 --dialect nope");
        INFO(r.out);
        CHECK(r.exit_code == 2);
        CHECK(contains(r.out, "nope"));
    }
}

TEST_CASE("kerf dialects --dialect-file adds a user dialect") {
    const fs::path file = fs::temp_directory_path() / ("kerf-test-user-dialect-" + std::to_string(getpid()) + ".toml");
    {
        std::ofstream out(file);
        out << "id = \"user-test-mill\"\n"
               "name = \"User test mill\"\n"
               "machine = \"mill\"\n"
               "overlay = false\n"
               "\n"
               "[lexical]\n"
               "semicolon = \"comment\"\n"
               "axes = [\"X\", \"Y\", \"Z\"]\n"
               "\n"
               "[[g]]\n"
               "code = \"G00\"\n"
               "group = \"01\"\n"
               "modal = true\n"
               "default = true\n"
               "function = \"rapid\"\n"
               "words = [\"X\", \"Y\", \"Z\"]\n"
               "en = \"Rapid positioning\"\n"
               "ru = \"Ускоренное позиционирование\"\n"
               "reference = \"test\"\n"
               "\n"
               "[[m]]\n"
               "code = \"M30\"\n"
               "function = \"program-end-rewind\"\n"
               "en = \"End of program\"\n"
               "ru = \"Конец программы\"\n"
               "reference = \"test\"\n";
    }
    const Run listed = kerf_cli("dialects --dialect-file " + shell_quote(file));
    const Run explained = kerf_cli("explain G0 --dialect user-test-mill --dialect-file " + shell_quote(file));
    fs::remove(file);
    {
        INFO(listed.out);
        CHECK(listed.exit_code == 0);
        CHECK(contains(listed.out, "user-test-mill"));
        CHECK(contains(listed.out, "User test mill"));
        CHECK(contains(listed.out, "fanuc-lathe-a"));   // the built-ins are still listed
    }
    {
        INFO(explained.out);
        CHECK(explained.exit_code == 0);
        CHECK(contains(explained.out, "Rapid positioning"));
    }
}

TEST_CASE("kerf dialects --dialect-file with a broken file fails with the line") {
    const fs::path file = fs::temp_directory_path() / ("kerf-test-broken-dialect-" + std::to_string(getpid()) + ".toml");
    {
        std::ofstream out(file);
        out << "id = \"broken\"\nname = \"Broken\"\nmachine = = \"mill\"\n";
    }
    const Run r = kerf_cli("dialects --dialect-file " + shell_quote(file));
    fs::remove(file);
    INFO(r.out);
    CHECK(r.exit_code == 2);
    // The position in the form of every kerf diagnostic (project/problem.hpp).
    CHECK(contains(r.out, file.string() + ":3:11: error: "));
}
