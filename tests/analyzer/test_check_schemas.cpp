// kerf check's machine-readable outputs against their schemas: --format sarif against the SARIF
// 2.1.0 schema (tests/schemas/sarif-2.1.0.json), --format json against docs/check-json.schema.json
// (docs/check-json.md), over the rule fixtures (every rule that can fire fires there, fixes
// included) and over the corpus. The validator itself is tested in tests/test_json_schema.cpp.
#include <catch2/catch.hpp>

#include <boost/json.hpp>
#include <filesystem>

#include "tests/cli/cli_runner.hpp"
#include "tests/json_schema.hpp"

namespace fs = std::filesystem;
namespace json = boost::json;
using namespace kerf::test;

namespace {

const fs::path kWork = fs::temp_directory_path() / "kerf-test-check-schemas";

struct Validated {
    json::value doc;
    std::vector<std::string> errors;
};

Validated validate_output(const JsonSchema& schema, const std::string& args, const std::string& work) {
    const CliRun r = run_kerf(args, kWork / work);
    INFO(args << "\n" << r.err);
    REQUIRE((r.code == 0 || r.code == 1));
    Validated v{json::parse(r.out), {}};
    v.errors = schema.validate(v.doc);
    return v;
}

void require_valid(const Validated& v) {
    for (const std::string& e : v.errors) FAIL_CHECK(e);
    CHECK(v.errors.empty());
}

std::size_t sarif_results(const json::value& doc) { return doc.at("runs").at(0).at("results").as_array().size(); }

const fs::path kFixtures = fs::path(KERF_SOURCE_DIR) / "tests/golden/check";
const fs::path kCorpus = fs::path(KERF_SHARED_DIR) / "corpus/";

}  // namespace

TEST_CASE("kerf check --format sarif over the rule fixtures validates against the SARIF 2.1.0 schema") {
    const JsonSchema sarif = load_schema(KERF_SOURCE_DIR "/tests/schemas/sarif-2.1.0.json");
    const Validated v = validate_output(sarif, "check --format sarif --dialect fanuc-mill " + shell_quote(kFixtures), "fixtures");
    require_valid(v);
    CHECK(sarif_results(v.doc) > 100);   // not an empty log that validates trivially
}

TEST_CASE("kerf check --format json over the rule fixtures validates against docs/check-json.schema.json") {
    const JsonSchema schema = load_schema(KERF_SOURCE_DIR "/docs/check-json.schema.json");
    const Validated v = validate_output(schema, "check --format json --dialect fanuc-lathe-a " + shell_quote(kFixtures), "fixtures-json");
    require_valid(v);
    const json::array& findings = v.doc.at("findings").as_array();
    CHECK(findings.size() > 100);
    // Fixes and hints are there, so their parts of the schema are exercised too.
    CHECK(std::any_of(findings.begin(), findings.end(), [](const json::value& f) { return f.as_object().contains("fix"); }));
    CHECK(std::any_of(findings.begin(), findings.end(), [](const json::value& f) { return f.as_object().contains("hint"); }));
}

// Every corpus file named on the command line (named files are checked whatever their name; a
// folder walk would skip test.src and the O-less files without extension).
TEST_CASE("kerf check over the corpus: SARIF and JSON both validate") {
    std::string paths;
    std::size_t count = 0;
    for (const fs::path& f : shared_files_or_warn("corpus schema test skipped"))
        if (f.string().starts_with(kCorpus.string())) paths += " " + shell_quote(f), ++count;
    if (count == 0) return;
    const Validated s = validate_output(load_schema(KERF_SOURCE_DIR "/tests/schemas/sarif-2.1.0.json"),
                                        "check --format sarif" + paths, "corpus-sarif");
    require_valid(s);
    CHECK(sarif_results(s.doc) > 50);
    const Validated j = validate_output(load_schema(KERF_SOURCE_DIR "/docs/check-json.schema.json"),
                                        "check --format json" + paths, "corpus-json");
    require_valid(j);
    CHECK(j.doc.at("files_checked").as_int64() == static_cast<std::int64_t>(count));
    CHECK(count == 60);
}

TEST_CASE("the schemas reject a wrong kerf document, so the tests above can fail") {
    const JsonSchema sarif = load_schema(KERF_SOURCE_DIR "/tests/schemas/sarif-2.1.0.json");
    const JsonSchema check = load_schema(KERF_SOURCE_DIR "/docs/check-json.schema.json");
    const json::value result = json::parse(
        R"({"ruleId":"K1003","level":"error","message":{"text":"m"},"locations":[{"physicalLocation":{"artifactLocation":{"uri":"a.nc"},"region":{"startLine":2,"startColumn":1}}}]})");
    const auto sarif_with = [](const json::value& r) {
        json::value log = json::parse(R"({"version":"2.1.0","runs":[{"tool":{"driver":{"name":"kerf"}},"results":[]}]})");
        log.at("runs").at(0).at("results").as_array().push_back(r);
        return log;
    };
    CHECK(sarif.validate(sarif_with(result)).empty());
    json::value bad = result;
    bad.as_object()["level"] = "info";   // not a SARIF level
    CHECK_FALSE(sarif.validate(sarif_with(bad)).empty());
    bad = result;
    bad.at("locations").at(0).at("physicalLocation").at("region").as_object()["startLine"] = 0;
    CHECK_FALSE(sarif.validate(sarif_with(bad)).empty());
    bad = result;
    bad.as_object().erase("message");
    CHECK_FALSE(sarif.validate(sarif_with(bad)).empty());
    CHECK_FALSE(sarif.validate(json::parse(R"({"version":"2.1.0","runs":[{"tool":{}}]})")).empty());

    json::value doc = json::parse(
        R"({"version":1,"tool":"kerf","files_checked":1,"summary":{"error":1,"warning":0,"info":0,"hint":0},
            "findings":[{"file":"a.nc","line":2,"column":1,"end_line":2,"end_column":4,"severity":"error",
                         "rule":"K1003","name":"letter-o-for-zero","message":"m","notes":[]}]})");
    CHECK(check.validate(doc).empty());
    doc.at("findings").at(0).as_object().erase("end_column");
    CHECK_FALSE(check.validate(doc).empty());
}
