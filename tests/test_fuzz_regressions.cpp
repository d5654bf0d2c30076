// Every input a fuzzer ever broke (fuzz/regressions/) passes its target's check again: the
// grammar's files (the directory itself) parse losslessly under every dialect, without crashing,
// overflowing the stack or taking quadratic time; fuzz/regressions/<target>/ hold the other
// targets' inputs, run through fuzz/checks.hpp.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ast/printer.hpp"
#include "ast/typed.hpp"
#include "fuzz/checks.hpp"
#include "grammar/parse.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Every file of fuzz/regressions/<target>/ through the target's check (fuzz/checks.hpp); returns
// how many there were.
std::size_t run_regressions(const char* target, kerf::fuzz::Broken (*check)(std::string_view)) {
    const fs::path dir = fs::path(KERF_SOURCE_DIR) / "fuzz" / "regressions" / target;
    std::size_t n = 0;
    if (!fs::is_directory(dir)) return n;
    for (const auto& e : fs::directory_iterator(dir)) {
        INFO(e.path().string());
        const kerf::fuzz::Broken broken = check(read_all(e.path()));
        CHECK(broken.value_or("") == "");
        ++n;
    }
    return n;
}

}  // namespace

// The seeds of each target pass its check too: the checks hold on ordinary programs.
TEST_CASE("fuzz checks hold on the seed corpus and the examples") {
    const fs::path corpus = fs::path(KERF_SOURCE_DIR) / "fuzz" / "corpus";
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(corpus)) {
        INFO(e.path().string());
        const std::string input = read_all(e.path());
        CHECK(kerf::fuzz::check_interpreter(input).value_or("") == "");
        CHECK(kerf::fuzz::check_analyzer(input).value_or("") == "");
        CHECK(kerf::fuzz::check_formatter(input).value_or("") == "");
        // Each seed into every dialect, both U/W styles and --expand (the option bits above the dialect).
        for (unsigned options = 0; options < 27; ++options) {
            std::string converted = input;
            converted[0] = static_cast<char>(static_cast<unsigned char>(input[0]) % 9 + 9 * options);
            INFO("convert, byte 0 = " << static_cast<int>(static_cast<unsigned char>(converted[0])));
            CHECK(kerf::fuzz::check_converter(converted).value_or("") == "");
        }
        // The decoder: no line limit / a 40-byte one, pieces of 1 and of 13 bytes.
        for (const char* options : {"\0\0", "\x28\x0c"})
            CHECK(kerf::fuzz::check_input(std::string(options, 2) + input.substr(1)).value_or("") == "");
        ++n;
    }
    CHECK(n >= 80);
    for (const auto& e : fs::directory_iterator(fs::path(KERF_SOURCE_DIR) / "machine" / "data")) {
        INFO(e.path().string());
        CHECK(kerf::fuzz::check_machine_toml(read_all(e.path())).value_or("") == "");
    }
    for (const auto& e : fs::directory_iterator(fs::path(KERF_SOURCE_DIR) / "dialects" / "data")) {
        INFO(e.path().string());
        CHECK(kerf::fuzz::check_dialect_toml(read_all(e.path())).value_or("") == "");
    }
}

TEST_CASE("fuzz regressions of the interpreter, analyzer, formatter, converter and TOML loaders stay fixed") {
    run_regressions("interpreter", kerf::fuzz::check_interpreter);
    run_regressions("analyzer", kerf::fuzz::check_analyzer);
    run_regressions("formatter", kerf::fuzz::check_formatter);
    run_regressions("converter", kerf::fuzz::check_converter);
    run_regressions("machine_toml", kerf::fuzz::check_machine_toml);
    run_regressions("dialect_toml", kerf::fuzz::check_dialect_toml);
    run_regressions("input", kerf::fuzz::check_input);
    run_regressions("kerf_toml", kerf::fuzz::check_kerf_toml);
    run_regressions("lsp", kerf::fuzz::check_lsp);
}

// The message loop's check on scripts written for it (fuzz/check_lsp.cpp reads one byte per message
// kind and the bytes after it; fuzz/make_seeds.py writes the same kinds of session as seeds).
TEST_CASE("fuzz check of the language server holds on hand-made message scripts") {
    using kerf::fuzz::check_lsp;
    const auto bytes = [](std::initializer_list<int> b) {
        std::string s;
        for (const int v : b) s += static_cast<char>(v);
        return s;
    };
    const std::string init = bytes({1, 0, 4}), initialized = bytes({2}), shutdown_exit = bytes({8, 9});
    const std::string open_lathe = bytes({3, 0, 1, 5});   // kPrograms[0] (5 % 4 != 0, 5 % 5 == 0)
    std::string every_request;
    for (int m = 0; m < 24; ++m) every_request += bytes({6, m, 0, 6, 9, 6, 0, 7, 0, 1, 6, 9, 6, 10, 0, 6, 0, 6, 5, 6, 0, 6, 5, 0});
    // A whole session through every request, then shutdown and exit (0).
    CHECK(check_lsp(init + initialized + open_lathe + every_request + shutdown_exit).value_or("") == "");
    // Edits inside and outside the document, a cancellation, waiting for the analysis; no exit (1).
    CHECK(check_lsp(init + initialized + open_lathe + bytes({4, 0, 2, 2, 5, 2, 5, 0, 4, 0, 4, 40, 0, 3, 1, 0, 7, 0, 14})).value_or("") == "");
    // A request before initialize, a binary document, broken framing, JSON that is not JSON-RPC.
    CHECK(check_lsp(bytes({6, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}) + init + bytes({3, 0, 1, 0, 2}) +
                    std::string("\0\0\0\0G0 X1", 8) + bytes({0, 5}) + "Conte" + bytes({12, 3}) + "{x}" + bytes({13, 2, 18, 7}) + shutdown_exit)
              .value_or("") == "");
}

// The decoder's target on inputs written for it: UTF-16 both ways with and without BOM, a CRLF
// split between two pieces, a lone CR at a piece's end, a line just over the limit.
TEST_CASE("fuzz check of the input decoder holds on hand-made inputs") {
    using kerf::fuzz::check_input;
    const std::string u16le("\xFF\xFEG\0""0\0 \0X\0""1\0\n\0", 14);
    const std::string u16be("\0G\0""0\0 \0X\0""1\0\n", 12);
    CHECK(check_input(std::string("\0\x01", 2) + u16le).value_or("") == "");
    CHECK(check_input(std::string("\0\x02", 2) + u16be).value_or("") == "");
    CHECK(check_input(std::string("\x05\x02", 2) + "G0\r\nX1\r\nY2345678\r").value_or("") == "");
    CHECK(check_input(std::string("\x05\x03", 2) + "G0\rX1\r\rY2345678\n").value_or("") == "");
    CHECK(check_input(std::string("\0\x00", 2) + "   \r\n\t").value_or("") == "");
    const std::string config = "dialect = 3\n[limits]\nmax_file_bytes = -1\n[nope]\n";
    CHECK(kerf::fuzz::check_kerf_toml(config).value_or("") == "");
}

TEST_CASE("fuzz regressions stay fixed") {
    const fs::path dir = fs::path(KERF_SOURCE_DIR) / "fuzz" / "regressions";
    REQUIRE(fs::is_directory(dir));
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.is_directory()) continue;   // the other targets' regressions (above)
        std::ifstream in(e.path(), std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        const std::string text = ss.str();
        INFO(e.path().filename().string());
        for (const std::string& id : kerf::dialects::builtin_registry().ids()) {
            const kerf::dialects::Dialect* d = kerf::dialects::builtin_registry().find(id);
            kerf::ast::SyntaxTree tree = kerf::grammar::parse(text, d->lexical);
            (void)kerf::ast::TypedFile::bind(tree, *d);
            REQUIRE(kerf::ast::print(tree) == text);
            REQUIRE_FALSE(kerf::ast::check_lossless(tree).has_value());
        }
        ++n;
    }
    CHECK(n >= 4);
}
