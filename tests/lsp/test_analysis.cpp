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
    // G71 from X40 Z2 down to the profile's X36 with cuts of 1 mm (radius), retract 0.5 mm, no
    // allowance (cycles.md §2): rapid X40→X38 (1 mm), cut Z2→Z-10 (12), retract at 45° to X39 Z-9.5
    // (0.707), rapid back to Z2 (11.5), rapid X39→X36 (1.5), cut Z2→Z-10 (12), rapid back to X40 Z2
    // (12.166): 3 feed moves, 4 rapids, 50.873 mm. At F0.2 mm/rev and 1000 rpm the cuts take
    // 3.600 + 0.212 + 3.600 s and the rapids 0.287 s in all (the time model of the machine): 7.7 s.
    REQUIRE(hints.size() == 2);
    CHECK(str(hints[1].at("label")) == "⟳ 3 feed · 4 rapid · 7.7 s");
    CHECK(test::span(json::object{{"start", hints[1].at("position")}, {"end", hints[1].at("position")}}) == "6:28-6:28");
    CHECK(str(hints[1].at("tooltip")) == "50.8726 mm of tool path in 7.7 s, from the dry run");
}

TEST_CASE("inlay hints: the values of macro expressions at their block in the dry run") {
    LspClient c;
    c.initialize(init_dialect("fanuc-mill"));
    const std::string text =
        "O0001\n"                      // 0
        "#1=5.\n"                      // 1   the assignment ends at 1:5
        "#2=#1*2\n"                    // 2   ends at 2:7
        "G01 X[#1+2.] Z-#2 F#1\n"      // 3   [#1+2.] 5-12, -#2 14-17, #1 19-21
        "#3=#5\n"                      // 4   #5 never set: vacant
        "M30\n";                       // 5
    c.open("file:///w/m.nc", text);
    c.diagnostics("file:///w/m.nc", 1);
    json::object p = test::doc("file:///w/m.nc");
    p["range"] = test::range(0, 0, 6, 0);
    std::vector<std::string> got;
    const json::array hints = c.result("textDocument/inlayHint", p).as_array();
    for (const json::value& h : hints)
        got.push_back(std::to_string(h.at("position").at("line").as_int64()) + ":" + std::to_string(h.at("position").at("character").as_int64()) + " " +
                      str(h.at("label")));
    std::sort(got.begin(), got.end());
    CHECK(got == std::vector<std::string>{"1:5 = 5", "2:7 = 10", "3:12 = 7", "3:17 = -10", "3:21 = 5", "4:5 = vacant"});
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

TEST_CASE("the dialect of a document: .kerf.toml, then the (DIALECT:) header, then detection; the client's kerf.dialect over all") {
    // G90 is the turning cycle in system A and absolute programming in B; G71 alone is metric input
    // in system C (dialects/data/fanuc-lathe-*.toml, gcode-tables.md §1).
    const std::string text = "(DIALECT: fanuc-lathe-b)\nO1\nG90 G00 X50. Z2.\nG71\nM30\n";   // G90 at 2:0-2:3, G71 at 3:0
    const auto hover = [](LspClient& c, const std::string& uri, std::uint32_t line) {
        return str(c.result("textDocument/hover", test::at(uri, line, 1)).at("contents").at("value"));
    };
    const auto has = [](const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; };
    SECTION("the header when no .kerf.toml names one") {
        test::TempFolder folder;
        LspClient c;
        c.initialize({}, folder.path());
        c.open(folder.uri("p.nc"), text);
        CHECK(has(hover(c, folder.uri("p.nc"), 2), "`absolute-programming`"));
    }
    SECTION(".kerf.toml over the header; the client's setting over both, at once") {
        test::TempFolder folder;
        folder.write(".kerf.toml", "dialect = \"fanuc-lathe-a\"\n");
        LspClient c;
        c.initialize({}, folder.path());
        c.log_containing("kerf lsp: indexed");
        c.open(folder.uri("p.nc"), text);
        CHECK(has(hover(c, folder.uri("p.nc"), 2), "`turning-cycle`"));
        c.notify("workspace/didChangeConfiguration", json::object{{"settings", json::object{{"kerf", json::object{{"dialect", "fanuc-lathe-c"}}}}}});
        c.log_containing("settings: dialect 'fanuc-lathe-c'");
        CHECK(has(hover(c, folder.uri("p.nc"), 3), "`metric-input`"));
    }
    SECTION("detection without header or configuration") {
        test::TempFolder folder;
        LspClient c;
        c.initialize({}, folder.path());
        // G71 U R / G71 P Q: the lathe roughing cycle of system A/B, not C's metric input.
        c.open(folder.uri("d.nc"), "O1\nG50 S2000\nG71 U1. R0.5\nG71 P10 Q20 U0.2 W0.1 F0.2\nN10 G00 X20.\nN20 G01 Z-10.\nM30\n");
        CHECK(has(hover(c, folder.uri("d.nc"), 2), "`rough-turning-cycle`"));
    }
}

TEST_CASE("the machine of a document: .kerf.toml machine =, or the client's kerf.machine") {
    // slow.toml: the built-in lathe with a 1500 rpm spindle (machine/SCHEMA.md max_spindle_rpm), so
    // S2000 is over the limit (K5021 at the S word, 1:4-1:9).
    test::TempFolder folder;
    folder.write("slow.toml", "id = \"slow\"\nbase = \"fanuc-lathe\"\nname = \"slow\"\nmax_spindle_rpm = 1500\n");
    const std::string text = "O1\nG97 S2000 M03\nG00 X10. Z1.\nM30\n";
    const auto k5021 = [](const json::array& d) {
        for (const json::value& v : d)
            if (str(v.at("code")) == "K5021") return span(v.at("range"));
        return std::string();
    };
    SECTION("from .kerf.toml") {
        folder.write(".kerf.toml", "dialect = \"fanuc-lathe-a\"\nmachine = \"slow.toml\"\n");
        LspClient c;
        c.initialize({}, folder.path());
        c.open(folder.uri("p.nc"), text);
        CHECK(k5021(c.diagnostics(folder.uri("p.nc"), 1)) == "1:4-1:9");
    }
    SECTION("from the client, and gone again when the client names none") {
        folder.write(".kerf.toml", "dialect = \"fanuc-lathe-a\"\n");
        LspClient c;
        c.initialize(json::object{{"initializationOptions", json::object{{"machine", (folder.path() / "slow.toml").string()}}}}, folder.path());
        c.log_containing("kerf lsp: indexed");   // its end analyses the open documents again: before they are open
        c.open(folder.uri("p.nc"), text);
        CHECK(k5021(c.diagnostics(folder.uri("p.nc"), 1)) == "1:4-1:9");
        c.notify("workspace/didChangeConfiguration", json::object{{"settings", json::object{{"kerf", json::object{{"machine", nullptr}}}}}});
        CHECK(k5021(c.diagnostics(folder.uri("p.nc"), 1)).empty());   // the built-in lathe: 4000 rpm
    }
}

TEST_CASE("open documents win over their files on disk in the workspace index") {
    test::TempFolder folder;
    folder.write(".kerf.toml", "dialect = \"fanuc-mill\"\n");
    folder.write("main.nc", "O1000\nM98 P2500\nM30\n");            // M98 P2500: "2500" at 1:5-1:9
    folder.write("sub.nc", "O2000 (ON DISK)\nG00 X1.\nM99\n");
    LspClient c;
    c.initialize({}, folder.path());
    c.log_containing("kerf lsp: indexed");
    c.open(folder.uri("main.nc"), "O1000\nM98 P2500\nM30\n");
    REQUIRE(by_code(c.diagnostics(folder.uri("main.nc"), 1)).count("K3003") == 1);   // no O2500 anywhere
    // The editor renumbers the subprogram without saving: main.nc is checked again at once.
    c.open(folder.uri("sub.nc"), "O2500 (EDITED)\nG00 X1.\nM99\n");
    CHECK(by_code(c.diagnostics(folder.uri("main.nc"), 1)).count("K3003") == 0);
    const json::value d = c.result("textDocument/definition", test::at(folder.uri("main.nc"), 1, 6));
    CHECK(str(d.at("uri")) == folder.uri("sub.nc"));
    CHECK(span(d.at("range")) == "0:0-0:5");
    // An edit of the open document keeps the index current: O2500 → O2600 and the call finds nothing.
    c.notify("textDocument/didChange", json::object{{"textDocument", json::object{{"uri", folder.uri("sub.nc")}, {"version", 2}}},
                                                     {"contentChanges", json::array{json::object{{"range", test::range(0, 2, 0, 3)}, {"text", "6"}}}}});
    CHECK(by_code(c.diagnostics(folder.uri("main.nc"), 1)).count("K3003") == 1);
    CHECK(c.result("textDocument/definition", test::at(folder.uri("main.nc"), 1, 6)).is_null());
    // Closed unsaved: the file on disk (O2000) counts again.
    c.notify("textDocument/didClose", json::object{{"textDocument", json::object{{"uri", folder.uri("sub.nc")}}}});
    CHECK(by_code(c.diagnostics(folder.uri("main.nc"), 1)).count("K3003") == 1);
}

namespace {

// A project whose loop.nc loops without end, on a machine that lets a dry run take a million
// million blocks (machine/SCHEMA.md max_blocks): only the wall-clock limit ends its dry run.
std::string endless_loop(const test::TempFolder& folder, LspClient& c, const char* time_limit) {
    folder.write("m.toml", "id = \"m\"\nbase = \"fanuc-mill\"\nname = \"m\"\n[switches]\nmax_blocks = 1000000000000\n");
    folder.write(".kerf.toml", std::string("dialect = \"fanuc-mill\"\nmachine = \"m.toml\"\n[limits]\ntime_limit = ") + time_limit + "\n");
    c.initialize({}, folder.path());
    c.open(folder.uri("loop.nc"), "O1\nN1 G01 X1. F100.\nG01 X2.\nGOTO 1\nM30\n");
    return folder.uri("loop.nc");
}

}  // namespace

TEST_CASE("hover and completion are answered while the dry run runs") {
    // The dry run may go on for a minute: the hover and the completion must come before its
    // diagnostics (which come when the run is cancelled at the end of the test, or never).
    test::TempFolder folder;
    LspClient c;
    const std::string uri = endless_loop(folder, c, "60");
    c.diagnostics(uri, 1, "static");
    const json::value h = c.result("textDocument/hover", test::at(uri, 1, 4));
    CHECK(str(h.at("contents").at("value")).find("**G01**") != std::string::npos);
    const json::value items = c.result("textDocument/completion", test::at(uri, 2, 1));
    CHECK(!items.at("items").as_array().empty());
    for (const json::object& m : c.history())
        if (m.contains("method") && m.at("method").as_string() == "textDocument/publishDiagnostics")
            CHECK(str(m.at("params").at("kerf").at("phase")) == "static");
}

TEST_CASE("the dry run stops at .kerf.toml [limits] time_limit, as kerf check's does") {
    test::TempFolder folder;
    LspClient c;
    const json::array d = c.diagnostics(endless_loop(folder, c, "0.2"), 1);
    const auto found = by_code(d);
    // The run's limit (alarm 90005, docs/trace.md) at whichever block of the loop ran when the
    // clock ran out.
    REQUIRE(found.count("K4004") == 1);
    CHECK(str(found.at("K4004")->at("message")).starts_with("time limit of 0.2 s reached"));
}

TEST_CASE("diagnostics take [programs] resident and a foreign control as kerf check does (project_check_options)") {
    // The server built its own check options and left these out: K3003 on every call of a probe
    // macro the machine keeps in memory, and 3D-printer files read as FANUC.
    test::TempFolder folder;
    folder.write(".kerf.toml", "[programs]\nresident = [\"O9000-O9999\"]\n");
    LspClient c;
    c.initialize({}, folder.path());
    c.open(folder.uri("main.nc"), "O0001\nM98 P9810\nM98 P7777\nG00 X0. Y0.\nM30\n");
    const json::array calls = c.diagnostics(folder.uri("main.nc"), 1);
    REQUIRE(codes(calls) == std::vector<std::string>{"K3003"});   // O7777 only: O9810 is resident
    CHECK(span(by_code(calls).at("K3003")->at("range")) == "2:4-2:9");
    c.open(folder.uri("print.gcode"), ";FLAVOR:Marlin\nM104 S200\nM140 S60\nG1 X10 Y10 F500\nM2\n");
    const json::array printer = c.diagnostics(folder.uri("print.gcode"), 1);
    REQUIRE(codes(printer) == std::vector<std::string>{"K2009"});   // one finding, nothing read as FANUC
    CHECK(str(printer[0].at("message")).find("3D printer") != std::string::npos);
}
