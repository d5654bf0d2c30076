// Diagnostics and what the dry run shows in the editor (issue 14 "Features"): the static findings
// first, the dry run's after; codes, links, related information, tags; the same suppressions,
// .kerf.toml rule settings and baseline as `kerf check`; the client's settings (pushed and
// pulled) and watched files re-analyse at once; inlay hints and code lens from the dry run.
#include <string>

#include "tests/lsp/lsp_client.hpp"

using namespace kerf;
using test::LspClient;
using test::span;
using test::str;
namespace json = boost::json;

namespace {

const std::string kDefects =
    "O0001\n"                      // 0
    "N10 G00 X0. Y0. X1.\n"        // 1   X0. 8-11, X1. 16-19: duplicate address (K1021)
    "N20 G01 X10. Y10. F100.\n"    // 2   a cut with no tool selected (K5008), found by the dry run
    "N30 G02 X20. Y0. R1.\n"       // 3   R1. cannot reach X20 (alarm 020, K5014), the dry run again
    "GOTO 10\n"                    // 4   N10 is on two blocks (K3002)
    "N10 M30\n"                    // 5
    "G00 X5.\n"                    // 6   after M30, nothing jumps here (K3007)
    "M30\n";                       // 7

std::map<std::string, const json::object*> by_code(const json::array& diagnostics) {
    std::map<std::string, const json::object*> out;
    for (const json::value& d : diagnostics) out[str(d.at("code"))] = &d.as_object();
    return out;
}

std::vector<std::string> codes(const json::array& diagnostics) {
    std::vector<std::string> out;
    for (const json::value& d : diagnostics) out.push_back(str(d.at("code")));
    return out;
}

json::object init_dialect(const char* dialect) { return {{"initializationOptions", json::object{{"dialect", dialect}}}}; }

}  // namespace

TEST_CASE("diagnostics: static findings first, the dry run's after, with codes, links, related places and tags") {
    LspClient c;
    c.initialize(init_dialect("fanuc-mill"));
    c.open("file:///w/d.nc", kDefects);
    const json::array first = c.diagnostics("file:///w/d.nc", 1, "static");
    CHECK(codes(first) == std::vector<std::string>{"K1021", "K3002", "K3007"});
    const json::array all = c.diagnostics("file:///w/d.nc", 1, "complete");
    CHECK(codes(all) == std::vector<std::string>{"K1021", "K5008", "K5014", "K3002", "K3007"});
    const auto d = by_code(all);
    const json::object& dup = *d.at("K1021");
    CHECK(span(dup.at("range")) == "1:16-1:19");
    CHECK(str(dup.at("source")) == "kerf");
    CHECK(dup.at("severity").as_int64() == 2);   // warning (docs/rules.md)
    CHECK(str(dup.at("codeDescription").at("href")).ends_with("/docs/rules.md#k1021-duplicate-address"));
    CHECK(span(dup.at("relatedInformation").as_array()[0].at("location").at("range")) == "1:8-1:11");   // the first X
    const json::array& labels = d.at("K3002")->at("relatedInformation").as_array();
    REQUIRE(labels.size() == 2);
    CHECK(span(labels[0].at("location").at("range")) == "1:0-1:19");
    CHECK(str(labels[0].at("message")) == "N10: the block the control jumps to");
    CHECK(span(labels[1].at("location").at("range")) == "5:0-5:7");
    CHECK(d.at("K3007")->at("tags").as_array()[0].as_int64() == 1);   // Unnecessary: greyed out
    CHECK(span(d.at("K3007")->at("range")) == "6:0-6:7");
    CHECK(d.at("K5014")->at("severity").as_int64() == 1);
    CHECK(span(d.at("K5014")->at("range")) == "3:0-3:20");
}

TEST_CASE("diagnostics follow inline suppressions, .kerf.toml [check.rules] and the baseline, as kerf check") {
    test::TempFolder folder;
    folder.write(".kerf.toml", "dialect = \"fanuc-mill\"\n[check.rules]\nK3007 = \"off\"\nK3002 = \"error\"\n");
    folder.write("baseline.json", R"({"version": 1, "findings": [{"file": "d.nc", "rule": "K5014", "block": "N30 G02 X20. Y0. R1."}]})");
    LspClient c;
    c.initialize(json::object{{"initializationOptions", json::object{{"baseline", (folder.path() / "baseline.json").string()}}}}, folder.path());
    std::string text = kDefects;
    text.replace(text.find("X1.\n"), 4, "X1. (kerf: ignore K1021)\n");
    c.open(folder.uri("d.nc"), text);
    const json::array all = c.diagnostics(folder.uri("d.nc"), 1);
    CHECK(codes(all) == std::vector<std::string>{"K5008", "K3002"});   // K1021 ignored, K3007 off, K5014 in the baseline
    CHECK(by_code(all).at("K3002")->at("severity").as_int64() == 1);            // raised to error
}

TEST_CASE("a new kerf.dialect setting re-analyses open documents at once, pushed or pulled") {
    const std::string text = "O0001\nG71 U1. R.5\nM30\n";   // G71 is stock removal on a lathe, inch/metric on no mill
    SECTION("pushed with didChangeConfiguration") {
        LspClient c;
        c.initialize(init_dialect("fanuc-mill"));
        c.open("file:///w/s.nc", text);
        CHECK(by_code(c.diagnostics("file:///w/s.nc", 1)).count("K2001") == 1);   // unknown code in fanuc-mill
        c.notify("workspace/didChangeConfiguration", json::object{{"settings", json::object{{"kerf", json::object{{"dialect", "fanuc-lathe-a"}}}}}});
        CHECK(by_code(c.diagnostics("file:///w/s.nc", 1)).count("K2001") == 0);
        const json::value h = c.result("textDocument/hover", test::at("file:///w/s.nc", 1, 1));
        CHECK(str(h.at("contents").at("value")).find("Stock removal in turning") != std::string::npos);
    }
    SECTION("pulled with workspace/configuration when the client can answer it") {
        LspClient c;
        c.initialize(json::object{{"capabilities", json::object{{"workspace", json::object{{"configuration", true}}}}}});
        const json::object ask = c.wait_for([](const json::object& m) { return m.contains("method") && m.at("method").as_string() == "workspace/configuration"; });
        CHECK(str(ask.at("params").at("items").as_array()[0].at("section")) == "kerf");
        c.open("file:///w/s.nc", text);
        c.diagnostics("file:///w/s.nc", 1);
        c.send_body(json::serialize(json::object{{"jsonrpc", "2.0"}, {"id", ask.at("id")},
                                                 {"result", json::array{json::object{{"dialect", "fanuc-mill"}}}}}));
        c.log_containing("settings: dialect 'fanuc-mill'");
        CHECK(by_code(c.diagnostics("file:///w/s.nc", 1)).count("K2001") == 1);
    }
}

TEST_CASE("watched files: a subprogram that appears on disk is found at once") {
    test::TempFolder folder;
    folder.write(".kerf.toml", "dialect = \"fanuc-mill\"\n");
    LspClient c;
    c.initialize({}, folder.path());
    c.log_containing("kerf lsp: indexed");
    c.open(folder.uri("main.nc"), "O0001\nM98 P4321\nM30\n");
    const json::array before = c.diagnostics(folder.uri("main.nc"), 1);
    REQUIRE(by_code(before).count("K3003") == 1);   // program O4321 is not there
    CHECK(span(by_code(before).at("K3003")->at("range")) == "1:4-1:9");
    folder.write("O4321.nc", "O4321 (NEW)\nG00 X1.\nM99\n");
    c.notify("workspace/didChangeWatchedFiles", json::object{{"changes", json::array{json::object{{"uri", folder.uri("O4321.nc")}, {"type", 1}}}}});
    CHECK(by_code(c.diagnostics(folder.uri("main.nc"), 1)).count("K3003") == 0);
    const json::value d = c.result("textDocument/definition", test::at(folder.uri("main.nc"), 1, 6));
    CHECK(str(d.at("uri")) == folder.uri("O4321.nc"));
}

TEST_CASE("inlay hints: absolute end points of incremental blocks, moves and time of cycle blocks") {
    LspClient c;
    c.initialize(init_dialect("fanuc-lathe-a"));
    const std::string text =
        "O0001\n"                                  // 0
        "N10 G99 S1000 M03 T0101\n"                // 1
        "N20 G00 X40. Z2.\n"                       // 2
        "N30 G01 U-10. W-5. F0.2\n"                // 3   incremental: ends at X30 Z-3
        "N40 G00 X40. Z2.\n"                       // 4
        "N50 G71 U1. R0.5\n"                       // 5
        "N60 G71 P70 Q80 U0. W0. F0.2\n"           // 6   the roughing passes (cycles.md §2)
        "N70 G00 X36.\n"                           // 7
        "N80 G01 Z-10.\n"                          // 8
        "M30\n";                                   // 9
    c.open("file:///w/h.nc", text);
    c.diagnostics("file:///w/h.nc", 1);
    json::object p = test::doc("file:///w/h.nc");
    p["range"] = test::range(0, 0, 10, 0);
    const json::array hints = c.result("textDocument/inlayHint", p).as_array();
    REQUIRE(hints.size() >= 2);
    CHECK(str(hints[0].at("label")) == "→ X30 Z-3");
    CHECK(test::span(json::object{{"start", hints[0].at("position")}, {"end", hints[0].at("position")}}) == "3:23-3:23");
    // G71 from X40 down to the profile's X36 with 1 mm radius cuts, allowance 0: two roughing levels
    // (X38, X36) and the final profile pass; the exact counts are the interpreter's (tests/interpreter).
    bool cycle = false;
    for (const json::value& h : hints)
        if (str(h.at("label")).starts_with("⟳ ") && h.at("position").at("line").as_int64() == 6) cycle = true;
    CHECK(cycle);
}

TEST_CASE("code lens: cycle time, path lengths and tools of the run on the main program, each subprogram's share") {
    LspClient c;
    c.initialize(init_dialect("fanuc-mill"));
    const std::string text =
        "O0001\nT1 M06\nG90 G00 X0. Y0. S1000 M03\nG01 X100. F1000.\nM98 P0002\nM30\n"   // 100 mm at 1000 mm/min: 6 s
        "O0002\nG01 Y60. F600.\nM99\n";                                                     // 60 mm at 600 mm/min: 6 s
    c.open("file:///w/l.nc", text);
    c.diagnostics("file:///w/l.nc", 1);
    const json::array lenses = c.result("textDocument/codeLens", test::doc("file:///w/l.nc")).as_array();
    std::vector<std::string> titles;
    for (const json::value& l : lenses) titles.push_back(std::to_string(l.at("range").at("start").at("line").as_int64()) + " " + str(l.at("command").at("title")));
    REQUIRE(titles.size() == 3);
    CHECK(titles[0].starts_with("0 cycle time "));
    CHECK(titles[0].find("feed 160.0 mm") != std::string::npos);   // 100 + 60 mm of feed moves
    CHECK(titles[1].starts_with("0 T1 "));
    CHECK(titles[2].starts_with("6 in the run: "));
    CHECK(titles[2].find("feed 60.0 mm") != std::string::npos);   // O0002's own feed move
}

TEST_CASE("a newer version supersedes the analysis of an older one: the last complete diagnostics are the last version's") {
    LspClient c;
    c.initialize(init_dialect("fanuc-mill"));
    std::string text = "O0001\n";
    for (int i = 0; i < 20000; ++i) text += "G01 X" + std::to_string(i % 100) + ". Y1. F100.\n";
    text += "M30\n";
    c.open("file:///w/v.nc", text);
    for (int v = 2; v <= 6; ++v)
        c.notify("textDocument/didChange", json::object{{"textDocument", json::object{{"uri", "file:///w/v.nc"}, {"version", v}}},
                                                         {"contentChanges", json::array{json::object{{"range", test::range(1, 0, 1, 0)}, {"text", "(E)"}}}}});
    c.diagnostics("file:///w/v.nc", 6);
    c.result("kerf/waitForAnalysis");
    // Nothing about an older version is published once the newest is in (the server publishes a
    // version only while it is the document's current one).
    const std::vector<json::object> all = c.history();
    std::size_t newest = 0, older_after = 0, complete = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (!all[i].contains("method") || all[i].at("method").as_string() != "textDocument/publishDiagnostics") continue;
        const std::int64_t v = all[i].at("params").at("version").as_int64();
        if (v == 6 && !newest) newest = i;
        if (newest && v < 6) ++older_after;
        complete += str(all[i].at("params").at("kerf").at("phase")) == "complete";
    }
    CHECK(newest > 0);
    CHECK(older_after == 0);
    CHECK(complete <= 6);   // at most one complete analysis per version; superseded ones are dropped
    const json::value h = c.result("textDocument/hover", test::at("file:///w/v.nc", 1, 16));
    CHECK(str(h.at("contents").at("value")).find("Dry run after this block") != std::string::npos);   // the analysis of version 6
}

TEST_CASE("the project layer decides: .kerf.toml problems are said, [programs] library folders are reached, K3010 as kerf check") {
    // proj/.kerf.toml reaches lib/ (a library folder); other/ is in the workspace but not reachable
    // by a call from proj/ (kerf check says K3003 there too), yet go to definition still finds it.
    test::TempFolder folder;
    folder.write("proj/.kerf.toml", "dialect = \"fanuc-mill\"\nmachin = \"m.toml\"\n[programs]\nlibrary = [\"../lib\"]\n");
    folder.write("lib/macros.nc", "%\nO9010 (PECK MACRO)\nG00 X1.\nM99\nO9011\nM99\n%\n");
    folder.write("other/O4444.nc", "O4444 (ELSEWHERE)\nM99\n");
    folder.write("proj/O5555.nc", "O5555 (COPY ONE)\nM99\n");
    folder.write("lib/O5555.nc", "O5555 (COPY TWO)\nM99\n");
    LspClient c;
    c.initialize({}, folder.path());
    c.log_containing("kerf lsp: indexed");
    c.open(folder.uri("proj/main.nc"), "O0001\nG65 P9010\nM98 P4444\nM98 P5555\nM30\n");
    // The strict .kerf.toml model (project/config.hpp): the misspelt key is said with its place.
    const json::object problem = c.log_containing("unknown key");
    CHECK(std::string(problem.at("params").at("message").as_string()).find(".kerf.toml:2:1") != std::string::npos);
    const json::array diagnostics = c.diagnostics(folder.uri("proj/main.nc"), 1);
    const auto d = by_code(diagnostics);
    REQUIRE(d.count("K3003") == 1);                                 // O4444 only: O9010 is in the library
    CHECK(span(d.at("K3003")->at("range")) == "2:4-2:9");
    REQUIRE(d.count("K3010") == 1);                                 // O5555 in proj/ and lib/: proj's copy runs
    CHECK(span(d.at("K3010")->at("range")) == "3:4-3:9");
    CHECK(str(d.at("K3010")->at("message")).find((folder.path() / "proj/O5555.nc").string()) != std::string::npos);
    // Definition: into the library file (a program inside a file named by content, not by number)...
    const json::value macro = c.result("textDocument/definition", test::at(folder.uri("proj/main.nc"), 1, 6));
    CHECK(str(macro.at("uri")) == folder.uri("lib/macros.nc"));
    CHECK(span(macro.at("range")) == "1:0-1:5");
    // ...and to the one file of the workspace that holds O4444, though no call from proj/ reaches it.
    const json::value other = c.result("textDocument/definition", test::at(folder.uri("proj/main.nc"), 2, 6));
    CHECK(str(other.at("uri")) == folder.uri("other/O4444.nc"));
    const json::value copy = c.result("textDocument/definition", test::at(folder.uri("proj/main.nc"), 3, 6));
    CHECK(str(copy.at("uri")) == folder.uri("proj/O5555.nc"));
}
