// Navigation features of `kerf lsp` over a small workspace (issue 14 "Features"): definition,
// references, rename, document highlight, call hierarchy, document and workspace symbols. Every
// expected position is read off the program text below by hand (lines 0-based, columns in UTF-16
// units = bytes here, as LSP counts them); the comment beside each line gives its number.
#include <string>

#include "tests/lsp/lsp_client.hpp"

using namespace kerf;
using test::LspClient;
using test::span;
using test::str;
namespace json = boost::json;

namespace {

const std::string kMain =
    "%\n"                                      // 0
    "O1000 (MAIN SHAFT)\n"                     // 1
    "N10 G50 S2000\n"                          // 2
    "N20 T0101\n"                              // 3
    "N30 G96 S200 M03\n"                       // 4
    "N40 G00 X50. Z2.\n"                       // 5
    "N50 G71 U1. R0.5\n"                       // 6
    "N60 G71 P70 Q90 U0.4 W0.1 F0.25\n"        // 7   P at 8, "70" 9-11, Q at 12, "90" 13-15
    "N70 G00 X20.\n"                           // 8
    "N80 G01 Z-20.\n"                          // 9
    "N90 X50.\n"                               // 10
    "N100 G70 P70 Q90\n"                       // 11  "70" 10-12, "90" 14-16
    "N110 M98 P31234\n"                        // 12  P at 9, "31234" 10-15: packed, 3 × O1234
    "N120 M98 P2000 Q200\n"                    // 13  "2000" 10-14, Q at 15, "200" 16-19
    "N130 G65 P9010 A1.\n"                     // 14  "9010" 10-14
    "N140 M30\n"                               // 15
    "O1234 (GROOVE SUB)\n"                     // 16
    "N5 G01 U-2. F0.1\n"                       // 17
    "N6 M99 P130\n"                            // 18  "130" 8-11
    "%\n";                                     // 19

const std::string kSub =
    "O2000 (SUB IN OTHER FILE)\n"              // 0
    "N100 G00 X30.\n"                          // 1
    "N200 G01 Z-5. F0.1\n"                     // 2
    "M99\n";                                   // 3

const std::string kMacro = "O9010 (PECK MACRO)\n#100=#1\nM99\n";

struct Workspace {
    test::TempFolder folder;
    LspClient client;
    std::string main, sub;
    explicit Workspace(bool open_sub = false) {
        folder.write(".kerf.toml", "dialect = \"fanuc-lathe-a\"\n");
        folder.write("main.nc", kMain);
        folder.write("sub.nc", kSub);
        folder.write("O9010", kMacro);
        main = folder.uri("main.nc");
        sub = folder.uri("sub.nc");
        client.initialize({}, folder.path());
        client.log_containing("kerf lsp: indexed");   // the workspace index is built
        client.open(main, kMain);
        if (open_sub) client.open(sub, kSub);
    }
};

json::object location(const json::value& v) { return v.is_array() ? v.as_array().at(0).as_object() : v.as_object(); }

// "uri-tail line:col-line:col" of a Location.
std::string where(const json::value& v) {
    const json::object& l = location(v);
    const std::string uri = str(l.at("uri"));
    return uri.substr(uri.rfind('/') + 1) + " " + span(l.at("range"));
}

std::vector<std::string> wheres(const json::value& v) {
    std::vector<std::string> out;
    for (const json::value& l : v.as_array()) out.push_back(where(l));
    return out;
}

// uri tail → "range=newText" of a WorkspaceEdit.
std::map<std::string, std::vector<std::string>> edits(const json::value& edit) {
    std::map<std::string, std::vector<std::string>> out;
    for (const auto& [uri, list] : edit.at("changes").as_object()) {
        const std::string u(uri);
        auto& v = out[u.substr(u.rfind('/') + 1)];
        for (const json::value& e : list.as_array()) v.push_back(span(e.at("range")) + "=" + str(e.at("newText")));
        std::sort(v.begin(), v.end());
    }
    return out;
}

}  // namespace

TEST_CASE("definition: labels of cycles, jumps and returns, programs in this file and across the workspace") {
    Workspace w;
    const auto def = [&](std::uint32_t line, std::uint32_t col) { return w.client.result("textDocument/definition", test::at(w.main, line, col)); };
    CHECK(where(def(7, 9)) == "main.nc 8:0-8:3");      // G71 P70 → N70
    CHECK(where(def(11, 14)) == "main.nc 10:0-10:3");  // G70 Q90 → N90
    CHECK(where(def(12, 11)) == "main.nc 16:0-16:5");  // M98 P31234 (packed) → O1234
    CHECK(where(def(13, 11)) == "sub.nc 0:0-0:5");     // M98 P2000 → O2000 in sub.nc (index)
    CHECK(where(def(13, 16)) == "sub.nc 2:0-2:4");     // M98 P2000 Q200 → N200 of O2000
    CHECK(where(def(14, 11)) == "O9010 0:0-0:5");      // G65 P9010 → the file O9010
    CHECK(where(def(18, 8)) == "main.nc 14:0-14:4");   // M99 P130 → N130 of the caller O1000
    CHECK(where(def(8, 1)) == "main.nc 8:0-8:3");      // on a label: itself
    CHECK(def(5, 5).is_null());                        // G00: nothing to go to
}

TEST_CASE("references: every jump to a label, every call of a program, across files") {
    Workspace w(true);
    const auto refs = [&](const std::string& uri, std::uint32_t line, std::uint32_t col, bool decl) {
        json::object p = test::at(uri, line, col);
        p["context"] = json::object{{"includeDeclaration", decl}};
        return wheres(w.client.result("textDocument/references", p));
    };
    CHECK(refs(w.main, 8, 1, true) == std::vector<std::string>{"main.nc 8:0-8:3", "main.nc 7:9-7:11", "main.nc 11:10-11:12"});
    CHECK(refs(w.main, 7, 10, false) == std::vector<std::string>{"main.nc 7:9-7:11", "main.nc 11:10-11:12"});
    CHECK(refs(w.main, 16, 2, true) == std::vector<std::string>{"main.nc 16:0-16:5", "main.nc 12:10-12:15"});
    // O2000 from its own file: the call in main.nc.
    CHECK(refs(w.sub, 0, 2, true) == std::vector<std::string>{"sub.nc 0:0-0:5", "main.nc 13:10-13:14"});
    // N200 of O2000: the M98 P2000 Q200 of main.nc.
    CHECK(refs(w.sub, 2, 1, false) == std::vector<std::string>{"main.nc 13:16-13:19"});
}

TEST_CASE("rename: a label with its references; a program with its calls, keeping each call's form") {
    Workspace w;
    const auto rename = [&](std::uint32_t line, std::uint32_t col, const std::string& name) {
        json::object p = test::at(w.main, line, col);
        p["newName"] = name;
        return w.client.request("textDocument/rename", p);
    };
    json::object r = rename(8, 1, "75");
    CHECK(edits(r.at("result")) == std::map<std::string, std::vector<std::string>>{{"main.nc", {"11:10-11:12=75", "7:9-7:11=75", "8:1-8:3=75"}}});
    // O1234 → O1240: the packed M98 P31234 keeps its repeat digit (the issue's example).
    r = rename(16, 2, "1240");
    CHECK(edits(r.at("result")) == std::map<std::string, std::vector<std::string>>{{"main.nc", {"12:10-12:15=31240", "16:1-16:5=1240"}}});
    // O2000 lives in sub.nc, which is not open: its O word is edited in the file too.
    r = rename(13, 11, "O2100");
    CHECK(edits(r.at("result")) == std::map<std::string, std::vector<std::string>>{{"main.nc", {"13:10-13:14=2100"}}, {"sub.nc", {"0:1-0:5=2100"}}});
    // Refusals (RequestFailed, -32803) say why.
    r = rename(8, 1, "80");   // N80 is a block of O1000 already
    CHECK(r.at("error").at("code").as_int64() == -32803);
    CHECK(str(r.at("error").at("message")).find("N80 is already on a block") != std::string::npos);
    r = rename(16, 2, "12345");   // the packed P31234 holds four digits of program
    CHECK(r.at("error").at("code").as_int64() == -32803);
    CHECK(str(r.at("error").at("message")).find("packs the program into four digits") != std::string::npos);
    r = rename(16, 2, "2000");   // O2000 exists in sub.nc
    CHECK(str(r.at("error").at("message")).find("O2000 already exists") != std::string::npos);
}

TEST_CASE("rename refuses, as kerf fmt does, where a label reference is computed") {
    LspClient c;
    c.initialize();
    const std::string text = "O0001\nN10 #1=1\nIF [#1 LT 3] GOTO #5\nN20 GOTO 10\nM30\n";
    c.open("file:///loop.nc", text);
    json::object p = test::at("file:///loop.nc", 1, 1);
    p["newName"] = "15";
    const json::object r = c.request("textDocument/rename", p);
    CHECK(r.at("error").at("code").as_int64() == -32803);
    CHECK(str(r.at("error").at("message")).find("'#5' at loop.nc:3 is computed") != std::string::npos);
}

TEST_CASE("prepareRename gives the number's range and its value; nothing on a code") {
    Workspace w;
    json::value r = w.client.result("textDocument/prepareRename", test::at(w.main, 8, 1));
    CHECK(span(r.at("range")) == "8:1-8:3");
    CHECK(str(r.at("placeholder")) == "70");
    r = w.client.result("textDocument/prepareRename", test::at(w.main, 12, 12));   // inside P31234
    CHECK(span(r.at("range")) == "12:10-12:15");
    CHECK(str(r.at("placeholder")) == "1234");
    CHECK(w.client.result("textDocument/prepareRename", test::at(w.main, 5, 5)).is_null());
}

TEST_CASE("document highlight: a label and its jumps; a code and its other blocks in the program") {
    Workspace w;
    json::value r = w.client.result("textDocument/documentHighlight", test::at(w.main, 8, 1));
    std::vector<std::string> got;
    for (const json::value& h : r.as_array()) got.push_back(span(h.at("range")) + ":" + std::to_string(h.at("kind").as_int64()));
    CHECK(got == std::vector<std::string>{"8:0-8:3:3", "7:9-7:11:2", "11:10-11:12:2"});
    r = w.client.result("textDocument/documentHighlight", test::at(w.main, 6, 5));   // G71
    got.clear();
    for (const json::value& h : r.as_array()) got.push_back(span(h.at("range")));
    CHECK(got == std::vector<std::string>{"6:4-6:7", "7:4-7:7"});
}

TEST_CASE("call hierarchy: who calls a program, whom it calls") {
    Workspace w;
    const json::value items = w.client.result("textDocument/prepareCallHierarchy", test::at(w.main, 16, 2));
    REQUIRE(items.as_array().size() == 1);
    const json::object& sub = items.as_array()[0].as_object();
    CHECK(str(sub.at("name")) == "O1234");
    CHECK(str(sub.at("detail")) == "GROOVE SUB");
    CHECK(span(sub.at("selectionRange")) == "16:0-16:5");
    const json::value incoming = w.client.result("callHierarchy/incomingCalls", json::object{{"item", sub}});
    REQUIRE(incoming.as_array().size() == 1);
    CHECK(str(incoming.as_array()[0].at("from").at("name")) == "O1000");
    CHECK(span(incoming.as_array()[0].at("fromRanges").as_array()[0]) == "12:10-12:15");
    // O1000 calls O1234 (this file), O2000 (sub.nc) and O9010 (macro file).
    const json::value main_item = w.client.result("textDocument/prepareCallHierarchy", test::at(w.main, 1, 2)).as_array()[0];
    const json::value outgoing = w.client.result("callHierarchy/outgoingCalls", json::object{{"item", main_item}});
    std::vector<std::string> to;
    for (const json::value& call : outgoing.as_array()) {
        const std::string uri = str(call.at("to").at("uri"));
        to.push_back(str(call.at("to").at("name")) + "@" + uri.substr(uri.rfind('/') + 1) + " " + span(call.at("fromRanges").as_array()[0]));
    }
    std::sort(to.begin(), to.end());
    CHECK(to == std::vector<std::string>{"O1234@main.nc 12:10-12:15", "O2000@sub.nc 13:10-13:14", "O9010@O9010 14:10-14:14"});
}

TEST_CASE("document symbols: programs with their labels and tool changes; workspace symbols by query") {
    Workspace w;
    const json::value symbols = w.client.result("textDocument/documentSymbol", test::doc(w.main));
    REQUIRE(symbols.as_array().size() == 2);
    const json::object& main = symbols.as_array()[0].as_object();
    CHECK(str(main.at("name")) == "O1000");
    CHECK(str(main.at("detail")) == "MAIN SHAFT");
    CHECK(span(main.at("range")) == "1:0-15:8");
    std::vector<std::string> children;
    for (const json::value& c : main.at("children").as_array()) children.push_back(str(c.at("name")) + "/" + std::to_string(c.at("kind").as_int64()));
    // N labels (kind 20 "Key" for jump targets, 16 "Number" for the others) and the tool change (24 "Event").
    CHECK(children == std::vector<std::string>{"N10/16", "N20/16", "T0101/24", "N30/16", "N40/16", "N50/16", "N60/16", "N70/20", "N80/16",
                                               "N90/20", "N100/16", "N110/16", "N120/16", "N130/20", "N140/16"});
    const json::value found = w.client.result("workspace/symbol", json::object{{"query", "other file"}});
    REQUIRE(found.as_array().size() == 1);
    CHECK(str(found.as_array()[0].at("name")) == "O2000");
    CHECK(where(found.as_array()[0].at("location")) == "sub.nc 0:0-0:0");
    const json::value by_number = w.client.result("workspace/symbol", json::object{{"query", "O9010"}});
    REQUIRE(by_number.as_array().size() == 1);
    CHECK(str(by_number.as_array()[0].at("containerName")) == "PECK MACRO");
}

TEST_CASE("definition and references of the other call forms: M98 P L, G66 P, GOTO; workspace symbols of labels") {
    test::TempFolder folder;
    folder.write(".kerf.toml", "dialect = \"fanuc-lathe-a\"\n");
    folder.write("O9010.nc", "O9010 (MODAL MACRO)\nG01 W-1.\nM99\n");
    const std::string text =
        "O1000 (MAIN)\n"              // 0
        "N10 M98 P1234 L3\n"          // 1   "1234" 9-13
        "N20 G66 P9010 A1.\n"         // 2   "9010" 9-13
        "N30 G00 X10.\n"              // 3
        "N40 G67\n"                   // 4
        "N50 GOTO 100\n"              // 5   "100" 9-12
        "N100 M30\n"                  // 6
        "O1234 (GROOVE)\n"            // 7
        "G01 U-1. F0.1\n"             // 8
        "M99\n";                      // 9
    folder.write("main.nc", text);
    LspClient c;
    c.initialize({}, folder.path());
    c.log_containing("kerf lsp: indexed");
    c.open(folder.uri("main.nc"), text);
    const auto def = [&](std::uint32_t line, std::uint32_t col) { return where(c.result("textDocument/definition", test::at(folder.uri("main.nc"), line, col))); };
    CHECK(def(1, 10) == "main.nc 7:0-7:5");     // M98 P1234 L3 → O1234
    CHECK(def(2, 10) == "O9010.nc 0:0-0:5");    // G66 P9010 → the macro's file
    CHECK(def(5, 10) == "main.nc 6:0-6:4");     // GOTO 100 → N100
    json::object p = test::at(folder.uri("main.nc"), 6, 1);
    p["context"] = json::object{{"includeDeclaration", false}};
    CHECK(wheres(c.result("textDocument/references", p)) == std::vector<std::string>{"main.nc 5:9-5:12"});
    p = test::at(folder.uri("main.nc"), 7, 2);
    p["context"] = json::object{{"includeDeclaration", false}};
    CHECK(wheres(c.result("textDocument/references", p)) == std::vector<std::string>{"main.nc 1:9-1:13"});
    // Workspace symbols: the O numbers and the labels, by query.
    const json::value labels = c.result("workspace/symbol", json::object{{"query", "N100"}});
    REQUIRE(labels.as_array().size() == 1);
    CHECK(str(labels.as_array()[0].at("containerName")) == "O1000");
    CHECK(where(labels.as_array()[0].at("location")) == "main.nc 6:0-6:8");
}
