// The language server's conversion actions (issue 16): "Convert this program to FANUC lathe, G-code
// system B (fanuc-lathe-b)" and the other dialects of the document's kind, as source.convert.kerf
// code actions whose edit is kerf convert's (tests/golden/convert has the rules); a small
// document's actions carry the edit and count what stays as it is, a large one's are resolved
// when chosen; a resolve for an older version is refused.
#include <string>

#include "tests/lsp/lsp_client.hpp"

using namespace kerf;
using test::LspClient;
using test::str;
namespace json = boost::json;

namespace {

const std::string kA = "O0001\nN10 G50 S2000\nN20 G99 G97 S500 M03\nN30 G00 X50. Z2.\nN40 G01 W-10. F0.2\nN50 X60.\nN60 M30\n";
const std::string kB = "O0001\nN10 G92 S2000\nN20 G95 G97 S500 M03\nN30 G00 X50. Z2.\nN40 G91 G01 Z-10. F0.2\nN50 G90 X60.\nN60 M30\n";
const std::string kC = "O0001\nN10 G92 S2000\nN20 G95 G97 S500 M03\nN30 G00 X50. Z2.\nN40 G91 G01 Z-10. F0.2\nN50 G90 X60.\nN60 M30\n";

// The text with the TextEdits of `edit` applied (ASCII text: UTF-16 columns are bytes).
std::string applied(std::string text, const json::value& edit, const std::string& uri) {
    const json::array& edits = edit.at("changes").at(uri).as_array();
    const auto offset = [&](const json::value& pos) {
        const std::int64_t line = pos.at("line").as_int64(), character = pos.at("character").as_int64();
        std::size_t at = 0;
        for (std::int64_t l = 0; l < line; ++l) at = text.find('\n', at) + 1;
        return at + static_cast<std::size_t>(character);
    };
    // Back to front, so the earlier offsets stay valid.
    for (std::size_t i = edits.size(); i-- > 0;) {
        const json::value& e = edits[i];
        const std::size_t begin = offset(e.at("range").at("start")), end = offset(e.at("range").at("end"));
        text.replace(begin, end - begin, std::string(e.at("newText").as_string()));
    }
    return text;
}

json::object conversions(const std::string& uri) {
    json::object p = test::doc(uri);
    p["range"] = test::range(0, 0, 0, 0);
    p["context"] = json::object{{"diagnostics", json::array{}}, {"only", json::array{"source.convert.kerf"}}};
    return p;
}

const json::object* action_to(const json::array& actions, const std::string& id) {
    for (const json::value& a : actions)
        if (str(a.at("title")).find("(" + id + ")") != std::string::npos) return &a.as_object();
    return nullptr;
}

}  // namespace

TEST_CASE("code actions: convert a system-A program to systems B and C, the other systems first") {
    LspClient client;
    client.initialize(json::object{{"initializationOptions", json::object{{"dialect", "fanuc-lathe-a"}}}});
    client.open("file:///w/a.nc", kA);
    const json::array actions = client.result("textDocument/codeAction", conversions("file:///w/a.nc")).as_array();
    // fanuc-lathe-b, fanuc-lathe-c (derived from A) before the other lathe dialects.
    REQUIRE(actions.size() >= 2);
    CHECK(str(actions[0].at("title")) == "Convert this program to FANUC lathe, G-code system B (fanuc-lathe-b)");
    CHECK(str(actions[1].at("title")) == "Convert this program to FANUC lathe, G-code system C (fanuc-lathe-c)");
    CHECK(str(actions[0].at("kind")) == "source.convert.kerf");
    CHECK(applied(kA, actions[0].at("edit"), "file:///w/a.nc") == kB);
    CHECK(applied(kA, actions[1].at("edit"), "file:///w/a.nc") == kC);
    // Only dialects for lathes are offered.
    CHECK(action_to(actions, "fanuc-mill") == nullptr);
    CHECK(action_to(actions, "adv400-lathe") != nullptr);
    // Not among the refactorings (renumber blocks): a client asking for those does not get them.
    json::object p = conversions("file:///w/a.nc");
    p["context"] = json::object{{"diagnostics", json::array{}}, {"only", json::array{"refactor"}}};
    const json::value refactorings = client.result("textDocument/codeAction", p);
    for (const json::value& a : refactorings.as_array()) CHECK(str(a.at("kind")) != "source.convert.kerf");
}

TEST_CASE("code actions: a conversion that leaves constructs says how many") {
    LspClient client;
    client.initialize(json::object{{"initializationOptions", json::object{{"dialect", "spinner-lathe-a"}}}});
    const std::string text = "O0002\nN10 G0 X100 Z100\nN20 G384 X0 C0 Z-15 R2 F1 S500 T1\nN30 G380\nN40 M30\n";
    client.open("file:///w/s.nc", text);
    const json::array actions = client.result("textDocument/codeAction", conversions("file:///w/s.nc")).as_array();
    const json::object* b = action_to(actions, "fanuc-lathe-b");
    REQUIRE(b != nullptr);
    CHECK(str(b->at("title")) == "Convert this program to FANUC lathe, G-code system B (fanuc-lathe-b): 2 left as they are");
    // spinner-lathe-b keeps the SPINNER codes: nothing left, nothing to change but G-code system names.
    const json::object* sb = action_to(actions, "spinner-lathe-b");
    REQUIRE(sb != nullptr);
    CHECK(str(sb->at("title")).find("left as") == std::string::npos);
    CHECK(applied(text, sb->at("edit"), "file:///w/s.nc") == text);
}

TEST_CASE("code actions: a large document's conversion is resolved when chosen, for its version only") {
    LspClient client;
    client.initialize(json::object{{"initializationOptions", json::object{{"dialect", "fanuc-lathe-a"}}}});
    std::string big = "O0003\nN1 G99 G97 S500 M03\n";
    for (int i = 0; i < 5000; ++i) big += "G00 X50. Z2.\nG01 W-10. F0.2\n";
    big += "M30\n";
    client.open("file:///w/big.nc", big);
    const json::array actions = client.result("textDocument/codeAction", conversions("file:///w/big.nc")).as_array();
    const json::object* b = action_to(actions, "fanuc-lathe-b");
    REQUIRE(b != nullptr);
    CHECK_FALSE(b->contains("edit"));
    const json::value resolved = client.result("codeAction/resolve", *b);
    const std::string converted = applied(big, resolved.at("edit"), "file:///w/big.nc");
    CHECK(converted.find("N1 G95 G97 S500 M03\nG00 X50. Z2.\nG91 G01 Z-10. F0.2\nG90 G00 X50. Z2.\n") != std::string::npos);
    // The document changed: the old action is refused.
    client.notify("textDocument/didChange",
                  json::object{{"textDocument", json::object{{"uri", "file:///w/big.nc"}, {"version", 2}}},
                               {"contentChanges", json::array{json::object{{"range", test::range(0, 0, 0, 0)}, {"text", "(NEW)\n"}}}}});
    CHECK(client.error_code("codeAction/resolve", *b) == -32801);   // ContentModified
}
