// Features of `kerf lsp` for reading and writing a program (issue 14 "Features"): hover,
// completion, semantic tokens, folding, selection range, formatting and range formatting, code
// actions, and features after incremental edits. Expected texts come from the dialect tables
// (dialects/data/fanuc-lathe-*.toml, quoted) and reference/cycles.md; positions are read off the
// program text, whose lines are numbered in the comments.
#include <string>

#include "tests/lsp/lsp_client.hpp"

using namespace kerf;
using test::LspClient;
using test::span;
using test::str;
namespace json = boost::json;

namespace {

const std::string kLathe =
    "O1000 (MAIN)\n"                           // 0
    "N10 G50 S2000\n"                          // 1
    "N20 T0101\n"                              // 2
    "N30 G96 S200 M03\n"                       // 3
    "N40 G00 X50. Z2.\n"                       // 4
    "N50 G71 U1. R0.5\n"                       // 5   G71 4-7, U1. 8-11
    "N60 G71 P70 Q90 U0.4 W0.1 F0.25\n"        // 6   U0.4 16-20
    "N70 G00 X20.\n"                           // 7
    "N80 G01 Z-20.\n"                          // 8
    "N90 X50.\n"                               // 9
    "N100 G70 P70 Q90\n"                       // 10
    "N110 G01 U-2. W-1.\n"                     // 11  U-2. 9-13
    "N120 G01 X10 Z-1\n"                       // 12  X10 9-12 (no point)
    "#100=#100+1\n"                            // 13  #100 0-4
    "N130 M30\n";                              // 14

// A client that opens documents under fanuc-lathe-a (the kerf.dialect setting) in English.
struct Session {
    LspClient client;
    json::value init;   // the initialize result
    explicit Session(const char* dialect = "fanuc-lathe-a", const char* language = "en") {
        init = client.initialize(json::object{{"initializationOptions", json::object{{"dialect", dialect}, {"language", language}}}});
    }
    std::string hover(const std::string& uri, std::uint32_t line, std::uint32_t col) {
        const json::value h = client.result("textDocument/hover", test::at(uri, line, col));
        return h.is_null() ? std::string() : str(h.at("contents").at("value"));
    }
};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::vector<std::string> labels(const json::value& completion) {
    std::vector<std::string> out;
    for (const json::value& i : completion.at("items").as_array()) out.push_back(str(i.at("label")));
    return out;
}

const json::object* item(const json::value& completion, const std::string& label) {
    for (const json::value& i : completion.at("items").as_array())
        if (str(i.at("label")) == label) return &i.as_object();
    return nullptr;
}

json::object completion_at(const std::string& uri, std::uint32_t line, std::uint32_t col) { return test::at(uri, line, col); }

}  // namespace

TEST_CASE("hover on a G code: the dialect's description, group, words and the other G-code systems") {
    Session s;
    s.client.open("file:///w/a.nc", kLathe);
    const json::value h = s.client.result("textDocument/hover", test::at("file:///w/a.nc", 5, 5));
    CHECK(span(h.at("range")) == "5:4-5:7");
    const std::string text = str(h.at("contents").at("value"));
    // fanuc-lathe-a.toml: G71 en = "Stock removal in turning (OD/ID roughing along Z)", group "00".
    CHECK(has(text, "**G71** — Stock removal in turning (OD/ID roughing along Z)"));
    CHECK(has(text, "`rough-turning-cycle` · group 00 (one-shot)"));
    CHECK(has(text, "Words: U W R P Q F S T · data, not axis moves: UW"));
    // System B keeps G71; system C calls it G73 and uses G71 for metric input (gcode-tables.md §2).
    CHECK(has(text, "- fanuc-lathe-b (B): G71"));
    CHECK(has(text, "- fanuc-lathe-c (C): G73; G71 there is Metric"));
}

TEST_CASE("hover in Russian when the client asks for it") {
    Session s("fanuc-lathe-a", "ru");
    s.client.open("file:///w/a.nc", kLathe);
    // fanuc-lathe-a.toml: G71 ru = "Цикл черновой продольной обработки (снятие припуска при точении)".
    CHECK(has(s.hover("file:///w/a.nc", 5, 5), "**G71** — Цикл черновой продольной обработки"));
    CHECK(has(s.hover("file:///w/a.nc", 5, 9), "глубина резания за проход Δd"));
}

TEST_CASE("hover on a word: its meaning in this block, and the value without a decimal point") {
    Session s;
    s.client.open("file:///w/a.nc", kLathe);
    // cycles.md §2: first-block U = depth of cut, second-block U = finishing allowance.
    CHECK(has(s.hover("file:///w/a.nc", 5, 9), "U in a G71 first block: depth of cut per pass Δd, radius, no sign (cycles.md §2)"));
    CHECK(has(s.hover("file:///w/a.nc", 6, 17), "U in a G71 second block: finishing allowance Δu in X, signed, diameter (cycles.md §2)"));
    CHECK(has(s.hover("file:///w/a.nc", 6, 9), "P in a G71 second block: first block (N) of the finishing profile"));
    CHECK(has(s.hover("file:///w/a.nc", 6, 9), "N70 → `N70 G00 X20.` (line 8)"));
    // In a motion block U is an incremental X move (system A: U/W incremental, dialects.md §3.3).
    CHECK(has(s.hover("file:///w/a.nc", 11, 10), "U: incremental move of axis X (G-code system A)"));
    // fanuc-lathe-a: calculator_decimal = false, so X10 counts least increments of 0.001 mm.
    CHECK(has(s.hover("file:///w/a.nc", 12, 10), "X10 without a point = 10 × 0.001 mm = 0.01 mm (least input increment)"));
    // Macro variables: the FANUC ranges.
    CHECK(has(s.hover("file:///w/a.nc", 13, 2), "**#100** — common variable (#100–#199)"));
}

TEST_CASE("hover shows the dry-run state at the block and the diagnostics under the cursor") {
    Session s;
    const std::string text = "O0001\nN10 G99 S500 M03 T0101\nN20 G00 X40. Z5.\nN30 G01 Z-10.\nM30\n";
    s.client.open("file:///w/b.nc", text);
    s.client.diagnostics("file:///w/b.nc", 1);   // the dry run of version 1 is done
    const std::string after_rapid = s.hover("file:///w/b.nc", 2, 1);
    CHECK(has(after_rapid, "**Dry run after this block**"));
    CHECK(has(after_rapid, "X 40 · "));
    CHECK(has(after_rapid, "Z 5 · "));
    CHECK(has(after_rapid, "T0101"));
    CHECK(has(after_rapid, "Modal: G00 "));
    // N30 G01 without any F: K5001 feed-move-without-feed, with the rule's documentation.
    const std::string on_move = s.hover("file:///w/b.nc", 3, 5);
    CHECK(has(on_move, "**K5001** feed-move-without-feed (error)"));
    // ...and the rule's explanation, as `kerf explain K5001` gives it (analyzer/rules/motion.cpp).
    CHECK(has(on_move, "A G01/G02/G03 move runs with no feed rate."));
    CHECK(has(on_move, "*semantics.md §4*"));
}

TEST_CASE("hover: a mill's state shows its tool as the program writes it (T5, not T0500)") {
    Session s("fanuc-mill");
    const std::string text = "O0002\nN10 T5 M06\nN20 G90 G00 X10. Y20. S1200 M03\nN30 G01 X30. F250.\nM30\n";
    s.client.open("file:///w/m.nc", text);
    s.client.diagnostics("file:///w/m.nc", 1);
    const std::string after_feed = s.hover("file:///w/m.nc", 3, 1);
    INFO(after_feed);
    CHECK(has(after_feed, "X 30 · Y 20"));
    CHECK(has(after_feed, "F 250 · S 1200 · T5"));
    CHECK_FALSE(has(after_feed, "T0500"));
    CHECK(has(after_feed, "Modal: G01 "));
}

TEST_CASE("completion: codes after G and M, cycle snippets in the dialect's own G-code system") {
    SECTION("system A: G71 and its two-block snippet") {
        Session s;
        s.client.open("file:///w/c.nc", "O1\nG7\nM30\n");
        const json::value r = s.client.result("textDocument/completion", completion_at("file:///w/c.nc", 1, 2));
        const json::object* g71 = item(r, "G71");
        REQUIRE(g71 != nullptr);
        CHECK(str(g71->at("detail")) == "Stock removal in turning (OD/ID roughing along Z)");
        CHECK(span(g71->at("textEdit").at("range")) == "1:0-1:2");   // replaces the typed "G7"
        const json::object* snippet = item(r, "G71 …");
        REQUIRE(snippet != nullptr);
        CHECK(snippet->at("insertTextFormat").as_int64() == 2);
        CHECK(str(snippet->at("textEdit").at("newText")) ==
              "G71 U${1:depth} R${2:retract}\nG71 P${3:first_N} Q${4:last_N} U${5:x_allowance} W${6:z_allowance} F${7:feed}");
        const json::value m = s.client.result("textDocument/completion", completion_at("file:///w/c.nc", 2, 1));
        REQUIRE(item(m, "M30") != nullptr);
        CHECK(item(m, "G71") == nullptr);
    }
    SECTION("system C: the same cycle is G73") {
        Session s("fanuc-lathe-c");
        s.client.open("file:///w/c.nc", "O1\nG7\nM30\n");
        const json::value r = s.client.result("textDocument/completion", completion_at("file:///w/c.nc", 1, 2));
        const json::object* snippet = item(r, "G73 …");
        REQUIRE(snippet != nullptr);
        CHECK(str(snippet->at("detail")) == "G73: stock removal in turning, two blocks (cycles.md §2)");
        CHECK(item(r, "G71 …") == nullptr);
    }
}

TEST_CASE("completion: labels after GOTO and G70 P, programs after M98 P, variables after #, words of the block") {
    Session s;
    const std::string text = "O1000\nN10 #1=0\nN20 #1=#1+1\nIF [#1 LT 3] GOTO \nG70 P\nM98 P\nG71 \nX#\nM30\nO2000 (TWO)\nM99\n";
    s.client.open("file:///w/d.nc", text);
    CHECK(labels(s.client.result("textDocument/completion", completion_at("file:///w/d.nc", 3, 18))) ==
          std::vector<std::string>{"20", "10"});   // the nearest first
    CHECK(labels(s.client.result("textDocument/completion", completion_at("file:///w/d.nc", 4, 5))) == std::vector<std::string>{"P20", "P10"});
    const json::value programs = s.client.result("textDocument/completion", completion_at("file:///w/d.nc", 5, 5));
    REQUIRE(item(programs, "P2000") != nullptr);
    CHECK(str(item(programs, "P2000")->at("detail")) == "TWO (this file)");
    std::vector<std::string> words = labels(s.client.result("textDocument/completion", completion_at("file:///w/d.nc", 6, 4)));
    std::sort(words.begin(), words.end());
    CHECK(words == std::vector<std::string>{"F", "P", "Q", "R", "S", "T", "U", "W"});   // G71's words (fanuc-lathe-a.toml)
    const json::value vars = s.client.result("textDocument/completion", completion_at("file:///w/d.nc", 7, 2));
    REQUIRE(item(vars, "#1") != nullptr);
    CHECK(has(str(item(vars, "#1")->at("detail")), "local variable"));
    REQUIRE(item(vars, "#3000") != nullptr);
}

TEST_CASE("semantic tokens: words by their bound role, G codes with their modal group") {
    Session s;
    s.client.open("file:///w/e.nc", "O1 (X)\nN10 G01 U-2. F0.1 T0101\n#1=#1+1\n");
    // The legend initialize answered: token types and modifiers by index.
    const json::array& types = s.init.at("capabilities").at("semanticTokensProvider").at("legend").at("tokenTypes").as_array();
    const json::array& modifiers = s.init.at("capabilities").at("semanticTokensProvider").at("legend").at("tokenModifiers").as_array();
    const json::array data = s.client.result("textDocument/semanticTokens/full", test::doc("file:///w/e.nc")).at("data").as_array();
    REQUIRE(data.size() % 5 == 0);
    std::vector<std::string> got;
    std::uint32_t line = 0, col = 0;
    for (std::size_t i = 0; i < data.size(); i += 5) {
        const auto dl = static_cast<std::uint32_t>(data[i].as_int64());
        col = dl ? static_cast<std::uint32_t>(data[i + 1].as_int64()) : col + static_cast<std::uint32_t>(data[i + 1].as_int64());
        line += dl;
        std::string mods;
        const auto bits = static_cast<std::uint32_t>(data[i + 4].as_int64());
        for (std::size_t b = 0; b < modifiers.size(); ++b)
            if (bits >> b & 1u) mods += "+" + str(modifiers[b]);
        got.push_back(std::to_string(line) + ":" + std::to_string(col) + "/" + std::to_string(data[i + 2].as_int64()) + " " +
                      str(types[static_cast<std::size_t>(data[i + 3].as_int64())]) + mods);
    }
    CHECK(got == std::vector<std::string>{"0:0/2 program", "0:3/3 comment", "1:0/3 label", "1:4/3 gcode+modal+group01",
                                          "1:8/4 axis+incremental", "1:13/4 feed", "1:18/5 tool", "2:0/2 variable+local",
                                          "2:3/2 variable+local", "2:6/1 number"});
    // The range request gives the tokens of the lines asked for.
    const json::array part = s.client.result("textDocument/semanticTokens/range",
                                              json::object{{"textDocument", json::object{{"uri", "file:///w/e.nc"}}}, {"range", test::range(2, 0, 3, 0)}})
                                 .at("data").as_array();
    CHECK(part.size() == 15);
    CHECK(part[0].as_int64() == 2);   // the first token on line 2
}

TEST_CASE("folding ranges: programs, WHILE loops, cycle profiles, comment runs") {
    Session s;
    const std::string text =
        "(HEADER ONE)\n(HEADER TWO)\n"       // 0 1
        "O1000\n"                            // 2
        "G71 U1. R.5\nG71 P10 Q30 U.2 W.1\n" // 3 4
        "N10 G00 X20.\nN20 G01 Z-5.\nN30 X40.\n"   // 5 6 7
        "#1=0\nWHILE [#1 LT 2] DO 1\n#1=#1+1\nEND 1\n"   // 8 9 10 11
        "M30\n";                             // 12
    s.client.open("file:///w/f.nc", text);
    std::vector<std::string> got;
    const json::value folds = s.client.result("textDocument/foldingRange", test::doc("file:///w/f.nc"));
    for (const json::value& f : folds.as_array())
        got.push_back(std::to_string(f.at("startLine").as_int64()) + "-" + std::to_string(f.at("endLine").as_int64()) +
                      (f.as_object().contains("kind") ? " " + str(f.at("kind")) : ""));
    std::sort(got.begin(), got.end());
    CHECK(got == std::vector<std::string>{"0-1 comment", "2-12 region", "5-7 region", "9-11"});
}

TEST_CASE("selection range: word, block, program, document") {
    Session s;
    s.client.open("file:///w/a.nc", kLathe);
    const json::value r = s.client.result("textDocument/selectionRange",
                                          json::object{{"textDocument", json::object{{"uri", "file:///w/a.nc"}}},
                                                       {"positions", json::array{json::object{{"line", 6}, {"character", 9}}}}});
    std::vector<std::string> chain;
    for (const json::value* node = &r.as_array()[0]; node;) {
        chain.push_back(span(node->at("range")));
        node = node->as_object().contains("parent") ? &node->at("parent") : nullptr;
    }
    CHECK(chain == std::vector<std::string>{"6:8-6:11", "6:0-6:31", "0:0-14:8", "0:0-15:0"});
}

TEST_CASE("formatting is kerf fmt: the style of .kerf.toml, refused with syntax errors; range formatting") {
    test::TempFolder folder;
    folder.write(".kerf.toml", "dialect = \"fanuc-mill\"\n[format]\nspacing = \"compact\"\n");
    LspClient c;
    c.initialize({}, folder.path());
    const std::string uri = folder.uri("p.nc");
    c.open(uri, "o0001\nn10 g0 x1.\nN20 G1 Y2. F100.\nM30\n");
    json::array edits = c.result("textDocument/formatting", test::doc(uri)).as_array();
    REQUIRE(edits.size() == 1);   // one edit over the lines that change
    CHECK(span(edits[0].at("range")) == "0:0-3:0");
    CHECK(str(edits[0].at("newText")) == "O0001\nN10G0X1.\nN20G1Y2.F100.\n");   // upper case (default) and compact (.kerf.toml)
    json::object p = test::doc(uri);
    p["range"] = test::range(1, 0, 1, 5);
    edits = c.result("textDocument/rangeFormatting", p).as_array();
    REQUIRE(edits.size() == 1);
    CHECK(str(edits[0].at("newText")) == "N10G0X1.\n");
    // A syntax error: not formatted, as kerf fmt.
    c.open(folder.uri("bad.nc"), "O0002\nG01 X-12.8. Y1.\nM30\n");
    const json::object r = c.request("textDocument/formatting", test::doc(folder.uri("bad.nc")));
    CHECK(r.at("error").at("code").as_int64() == -32803);
    CHECK(has(str(r.at("error").at("message")), "not formatted: 1 syntax error (the first at line 2"));
}

TEST_CASE("code actions: a rule's fix as a quick fix; renumber blocks with every reference moved") {
    Session s("fanuc-mill");
    s.client.open("file:///w/g.nc", "O0001\nN5 T1 MO6\nM30\n");   // MO6: the letter O for zero (K1003)
    s.client.diagnostics("file:///w/g.nc", 1);
    json::object p = test::doc("file:///w/g.nc");
    p["range"] = test::range(1, 6, 1, 9);
    p["context"] = json::object{{"diagnostics", json::array{}}};
    const json::object* fix = nullptr;
    const json::array actions = s.client.result("textDocument/codeAction", p).as_array();
    for (const json::value& a : actions)
        if (str(a.at("kind")) == "quickfix") fix = &a.as_object();
    REQUIRE(fix != nullptr);
    CHECK(has(str(fix->at("title")), "(K1003)"));
    const json::array& fix_edits = fix->at("edit").at("changes").at("file:///w/g.nc").as_array();
    REQUIRE(fix_edits.size() == 1);
    CHECK(span(fix_edits[0].at("range")) == "1:6-1:9");   // the word MO6 ...
    CHECK(str(fix_edits[0].at("newText")) == "M06");      // ... with the digit 0 (analyzer/rules/syntax.cpp)

    s.client.open("file:///w/r.nc", "O0002\nN5 T1 M06\nN7 G00 X0. Y0.\nGOTO 7\nM30\n");
    p = test::doc("file:///w/r.nc");
    p["range"] = test::range(0, 0, 0, 0);
    p["context"] = json::object{{"diagnostics", json::array{}}, {"only", json::array{"refactor.rewrite"}}};
    const json::array renumber = s.client.result("textDocument/codeAction", p).as_array();
    REQUIRE(renumber.size() == 1);
    CHECK(str(renumber[0].at("title")) == "Renumber blocks (N10, step 10)");
    // Every code block numbered from N10 by 10 (the O line is not a code block); GOTO 7 follows N7,
    // now N20 (formatter/renumber.hpp); nothing else of the text changes. The edit covers the bytes
    // that differ, from the start of the first changed line: "M30\n" at the end stays.
    const json::array& re = renumber[0].at("edit").at("changes").at("file:///w/r.nc").as_array();
    REQUIRE(re.size() == 1);
    CHECK(span(re[0].at("range")) == "1:0-4:0");
    CHECK(str(re[0].at("newText")) == "N10 T1 M06\nN20 G00 X0. Y0.\nN30 GOTO 20\nN40 ");
}

TEST_CASE("renumber blocks is disabled with the planner's reason when a jump is computed") {
    Session s("fanuc-mill");
    s.client.open("file:///w/h.nc", "O0001\nN10 #1=10\nGOTO #1\nM30\n");
    json::object p = test::doc("file:///w/h.nc");
    p["range"] = test::range(0, 0, 0, 0);
    p["context"] = json::object{{"diagnostics", json::array{}}, {"only", json::array{"refactor"}}};
    const json::array actions = s.client.result("textDocument/codeAction", p).as_array();
    REQUIRE(actions.size() == 1);
    CHECK(has(str(actions[0].at("disabled").at("reason")), "GOTO '#1' is computed"));
}

TEST_CASE("features see each incremental edit at once") {
    Session s;
    s.client.open("file:///w/i.nc", kLathe);
    // Insert a block before line 5 and change U1. to U2. on what is then line 6.
    s.client.notify("textDocument/didChange",
                    json::object{{"textDocument", json::object{{"uri", "file:///w/i.nc"}, {"version", 2}}},
                                 {"contentChanges", json::array{json::object{{"range", test::range(5, 0, 5, 0)}, {"text", "N45 G72 W1. R.5\n"}},
                                                                json::object{{"range", test::range(6, 8, 6, 10)}, {"text", "U2"}}}}});
    CHECK(has(s.hover("file:///w/i.nc", 5, 5), "**G72**"));
    CHECK(has(s.hover("file:///w/i.nc", 5, 9), "W in a G72 first block: depth of cut per pass Δd in Z (cycles.md §3)"));
    const json::value h = s.client.result("textDocument/hover", test::at("file:///w/i.nc", 6, 9));
    CHECK(span(h.at("range")) == "6:8-6:11");
    // Definitions follow the moved lines: G71 P70 (now line 7) → N70 (now line 8).
    const json::value d = s.client.result("textDocument/definition", test::at("file:///w/i.nc", 7, 9));
    CHECK(span(d.at("range")) == "8:0-8:3");
    s.client.diagnostics("file:///w/i.nc", 2);   // the new version is analysed
}

TEST_CASE("hover on a variable: its value after the block in the dry run; a system variable's meaning") {
    Session s("fanuc-mill");
    const std::string text =
        "O0001\n"                      // 0
        "#1=5.\n"                      // 1
        "#2=#1*2\n"                    // 2   #2 0-2, #1 3-5
        "G01 X[#1+2.] Z-#2 F#1\n"      // 3
        "#3=#5+#3001\n"                // 4   #5 3-5 (never set), #3001 6-11
        "M30\n";                       // 5
    s.client.open("file:///w/v.nc", text);
    s.client.diagnostics("file:///w/v.nc", 1);   // the dry run of version 1 is done
    const std::string two = s.hover("file:///w/v.nc", 2, 1);
    CHECK(has(two, "**#2** — local variable (#1–#33)"));
    CHECK(has(two, "Value after this block in the dry run: **10**"));   // #1 * 2 with #1 = 5
    CHECK(has(s.hover("file:///w/v.nc", 2, 4), "Value after this block in the dry run: **5**"));
    CHECK(has(s.hover("file:///w/v.nc", 4, 4), "Value after this block in the dry run: **vacant**"));
    const std::string clock = s.hover("file:///w/v.nc", 4, 8);
    CHECK(has(clock, "**#3001** — system variable (#3001): clock 1 in ms (the dry-run time)"));   // lsp/features/variables.cpp
}

TEST_CASE("hover on a call: the called program's first comment and its file; the repeat count") {
    test::TempFolder folder;
    folder.write(".kerf.toml", "dialect = \"fanuc-lathe-a\"\n");
    folder.write("sub.nc", "O2000 (SUB IN OTHER FILE)\nM99\n");
    LspClient c;
    c.initialize({}, folder.path());
    c.log_containing("kerf lsp: indexed");
    c.open(folder.uri("main.nc"), "O1000\nM98 P31234\nM98 P2000\nM30\nO1234 (GROOVE SUB)\nM99\n");
    const auto hover = [&](std::uint32_t line, std::uint32_t col) {
        return str(c.result("textDocument/hover", test::at(folder.uri("main.nc"), line, col)).at("contents").at("value"));
    };
    const std::string packed = hover(1, 6);   // P31234: three times O1234 (dialects.md §3.6)
    CHECK(has(packed, "**O1234** — GROOVE SUB · 3 times"));
    CHECK(has(packed, "File: `this file`"));
    const std::string other = hover(2, 6);
    CHECK(has(other, "**O2000** — SUB IN OTHER FILE"));
    CHECK(has(other, "File: `" + (folder.path() / "sub.nc").string() + "`"));
}

TEST_CASE("completion: programs after G65 P, the caller's labels after M99 P, labels after G70 Q, G76 snippets per system") {
    Session s;
    const std::string text =
        "O1000\n"               // 0
        "N10 G00 X1.\n"         // 1
        "N20 G65 P\n"           // 2   P at 8, cursor 9
        "N30 G70 P10 Q\n"       // 3   Q at 12, cursor 13
        "N40 M98 P2000\n"       // 4
        "M30\n"                 // 5
        "O2000 (TWO)\n"         // 6
        "N5 G01 X2.\n"          // 7
        "M99 P\n";              // 8   P at 4, cursor 5
    s.client.open("file:///w/c.nc", text);
    const json::value programs = s.client.result("textDocument/completion", completion_at("file:///w/c.nc", 2, 9));
    CHECK(labels(programs) == std::vector<std::string>{"P1000", "P2000"});
    CHECK(span(item(programs, "P2000")->at("textEdit").at("range")) == "2:8-2:9");
    // G70 Q: the labels of this program, the nearest first.
    const json::value q = s.client.result("textDocument/completion", completion_at("file:///w/c.nc", 3, 13));
    CHECK(labels(q) == std::vector<std::string>{"Q30", "Q20", "Q40", "Q10"});
    CHECK(span(item(q, "Q30")->at("textEdit").at("range")) == "3:12-3:13");
    // M99 P in O2000 returns into its caller O1000 (M98 P2000 at N40): the caller's labels.
    const json::value back = s.client.result("textDocument/completion", completion_at("file:///w/c.nc", 8, 5));
    CHECK(labels(back) == std::vector<std::string>{"P40", "P30", "P20", "P10"});
    SECTION("system A: G76 two blocks") {
        s.client.open("file:///w/t.nc", "O1\nG7\nM30\n");
        const json::value r = s.client.result("textDocument/completion", completion_at("file:///w/t.nc", 1, 2));
        const json::object* g76 = item(r, "G76 …");
        REQUIRE(g76 != nullptr);
        CHECK(str(g76->at("textEdit").at("newText")) ==
              "G76 P${1:02}${2:00}${3:60} Q${4:min_depth} R${5:finish_allowance}\n"
              "G76 X${6:root_diameter} Z${7:end_z} R${8:0} P${9:height} Q${10:first_depth} F${11:lead}");
    }
    SECTION("system C: the same cycle is G78") {
        Session c("fanuc-lathe-c");
        c.client.open("file:///w/t.nc", "O1\nG7\nM30\n");
        const json::value r = c.client.result("textDocument/completion", completion_at("file:///w/t.nc", 1, 2));
        REQUIRE(item(r, "G78 …") != nullptr);
        CHECK(str(item(r, "G78 …")->at("textEdit").at("newText")).starts_with("G78 P${1:02}${2:00}${3:60} Q"));
        REQUIRE(item(r, "G76 …") != nullptr);   // G76 is face peck drilling in system C (gcode-tables.md §1)
        CHECK(str(item(r, "G76 …")->at("detail")) == "G76: face peck drilling / grooving, two blocks (cycles.md §5)");
    }
}

TEST_CASE("semantic tokens: spindle words, common and system variables, macro keywords, operators and functions") {
    Session s("fanuc-mill");
    s.client.open("file:///w/k.nc", "O2\nN5 S1200 M03\nWHILE [#100 LT #5001] DO 1\n#100=SQRT[#100]+1\nEND 1\nM99\n");
    const json::array& types = s.init.at("capabilities").at("semanticTokensProvider").at("legend").at("tokenTypes").as_array();
    const json::array& modifiers = s.init.at("capabilities").at("semanticTokensProvider").at("legend").at("tokenModifiers").as_array();
    const json::array data = s.client.result("textDocument/semanticTokens/full", test::doc("file:///w/k.nc")).at("data").as_array();
    std::vector<std::string> got;
    std::uint32_t line = 0, col = 0;
    for (std::size_t i = 0; i + 4 < data.size(); i += 5) {
        const auto dl = static_cast<std::uint32_t>(data[i].as_int64());
        col = dl ? static_cast<std::uint32_t>(data[i + 1].as_int64()) : col + static_cast<std::uint32_t>(data[i + 1].as_int64());
        line += dl;
        std::string mods;
        for (std::size_t b = 0; b < modifiers.size(); ++b)
            if (static_cast<std::uint32_t>(data[i + 4].as_int64()) >> b & 1u) mods += "+" + str(modifiers[b]);
        got.push_back(std::to_string(line) + ":" + std::to_string(col) + "/" + std::to_string(data[i + 2].as_int64()) + " " +
                      str(types[static_cast<std::size_t>(data[i + 3].as_int64())]) + mods);
    }
    // Columns read off the text: "WHILE [#100 LT #5001] DO 1" has WHILE 0-4, #100 7-10, LT 12-13,
    // #5001 15-19, DO 22-23, 1 at 25; "#100=SQRT[#100]+1" has #100 0-3, SQRT 5-8, #100 10-13, 1 at 16.
    CHECK(got == std::vector<std::string>{"0:0/2 program", "1:0/2 label", "1:3/5 spindle", "1:9/3 mcode", "2:0/5 keyword",
                                          "2:7/4 variable+common", "2:12/2 operator", "2:15/5 variable+system", "2:22/2 keyword",
                                          "2:25/1 number", "3:0/4 variable+common", "3:5/4 function", "3:10/4 variable+common",
                                          "3:16/1 number", "4:0/3 keyword", "4:4/1 number", "5:0/3 mcode"});
}
