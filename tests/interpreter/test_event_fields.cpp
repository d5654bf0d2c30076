// The one list of event fields (interpreter/event_fields.hpp) against everything that must follow
// it: the trace's JSON schema (docs/trace.schema.json), the table of docs/trace.md, the traces of
// every reference example and corpus file, and `kerf fmt --verify`'s comparison.
#include <catch2/catch.hpp>

#include <boost/json.hpp>

#include <algorithm>
#include <set>
#include <string>

#include "interpreter/event_fields.hpp"
#include "interpreter/trace_compare.hpp"
#include "interpreter/trace_json.hpp"
#include "tests/interpreter/interpreter_fixture.hpp"
#include "tests/json_schema.hpp"
#include "tests/shared_files.hpp"

namespace json = boost::json;
namespace fs = std::filesystem;
using namespace kerf;
using interpreter::EventField;
using interpreter::FieldType;

namespace {

const fs::path kSchema = fs::path(KERF_SOURCE_DIR) / "docs" / "trace.schema.json";

std::set<std::string> field_keys() {
    std::set<std::string> keys;
    for (const EventField& f : interpreter::event_fields()) keys.emplace(f.key);
    return keys;
}

// The JSON type a field's type is written as.
std::string json_type_of(FieldType t) {
    switch (t) {
        case FieldType::position: return "object";
        case FieldType::number: return "number";
        case FieldType::integer: return "integer";
        case FieldType::flag: return "boolean";
        case FieldType::text: return "string";
    }
    return "";
}

// The trace lines of a run, as `kerf run --trace` writes them, parsed.
std::vector<json::object> trace_of(const test::SharedFileRun& run, std::size_t at_most) {
    interpreter::TraceWriter writer(run.programs, "XYZABC");
    std::vector<json::object> lines;
    for (const test::Event& e : run.events) {
        if (lines.size() == at_most) break;
        fmt::memory_buffer line;
        writer.append(line, e);
        lines.push_back(json::parse(std::string_view(line.data(), line.size())).as_object());
    }
    return lines;
}

}  // namespace

TEST_CASE("the trace schema has exactly the list's keys, with the list's types") {
    const json::value schema = json::parse(test::read_text(kSchema));
    const json::object& properties = schema.at("properties").as_object();
    std::set<std::string> schema_keys;
    for (const auto& p : properties) schema_keys.emplace(p.key());
    CHECK(schema_keys == field_keys());
    for (const EventField& f : interpreter::event_fields()) {
        INFO(f.key);
        const json::object& property = properties.at(f.key).as_object();
        if (f.member == interpreter::EventMember::kind || f.member == interpreter::EventMember::units) continue;   // enum, const
        if (f.type == FieldType::position) CHECK(property.at("$ref").as_string() == "#/definitions/position");
        else CHECK(property.at("type").as_string() == json_type_of(f.type));
    }
    // Fields written for every event are required.
    std::set<std::string> required;
    for (const json::value& r : schema.at("required").as_array()) required.emplace(r.as_string());
    std::set<std::string> always;
    const test::Event plain{};   // a rapid with nothing else: what every event has
    for (const EventField& f : interpreter::event_fields()) {
        test::Event dwell;
        dwell.kind = test::EventKind::dwell;
        if (f.written(plain) && f.written(dwell)) always.emplace(f.key);
    }
    CHECK(required == always);
}

TEST_CASE("docs/trace.md documents every key of the list in its table") {
    const std::string doc = test::read_text(fs::path(KERF_SOURCE_DIR) / "docs" / "trace.md");
    const std::size_t table = doc.find("## Trace line");
    REQUIRE(table != std::string::npos);
    const std::string section = doc.substr(table, doc.find("\n\n**", table) - table);
    for (const std::string& key : field_keys()) {
        INFO(key);
        CHECK(section.find("`" + key + "`") != std::string::npos);
    }
}

TEST_CASE("the traces of every reference example and corpus file follow the schema") {
    const std::vector<fs::path> files = test::shared_files_or_warn("the trace schema sweep was not run");
    if (files.empty()) return;
    const test::JsonSchema schema = test::load_schema(kSchema.string());
    interpreter::RunOptions options;
    options.emit_state = true;   // the state events too
    std::size_t checked = 0;
    for (const fs::path& path : files) {
        INFO(path.string());
        const std::optional<test::SharedFileRun> run = test::run_shared_file(path, options);
        if (!run) continue;
        // The first 3000 events of each file: every kind of event the file has appears long before
        // in every file of the sweep, and the big CAM files would otherwise dominate the time.
        for (const json::object& line : trace_of(*run, 3000)) {
            const std::vector<std::string> errors = schema.validate(line);
            INFO(json::serialize(line));
            CHECK(errors.empty());
            if (!errors.empty()) FAIL_CHECK(errors.front());
            ++checked;
        }
    }
    CHECK(checked > 50'000);
}

TEST_CASE("a G34 thread and an inch program write lead_end and units, and the schema takes them") {
    const test::JsonSchema schema = test::load_schema(kSchema.string());
    std::size_t lead_end = 0, units = 0;
    for (const auto& [text, id] : {std::pair{"G97 S500 M03\nG00 X30. Z5.\nG34 Z-30. F2. K0.1\nM30\n", "fanuc-lathe-a"},
                                   std::pair{"G20\nG00 X1. Y1.\nG01 X2. F10.\nM30\n", "fanuc-mill"}}) {
        const dialects::Dialect& d = test::dialect(id);
        interpreter::ProgramSet programs;
        const auto main = programs.first_program(programs.add("t.nc", text, d));
        REQUIRE(main);
        interpreter::VectorSink sink;
        interpreter::run(programs, *main, d, test::plain_setup(d), sink);
        for (const test::Event& e : sink.events) {
            const json::object line = interpreter::event_to_json(e, programs, "XYZ");
            INFO(json::serialize(line));
            CHECK(schema.validate(line).empty());
            lead_end += line.contains("lead_end");
            units += line.contains("units");
        }
    }
    CHECK(lead_end == 1);
    CHECK(units >= 2);
}

// A dialect that numbers an alarm itself ([alarms]; the made-up "Test NGC" table of
// tests/dialects/test_alarms.cpp): the trace keeps kerf's number as the code and writes the
// control's as control_alarm, which the schema takes; --verify compares it.
TEST_CASE("an alarm the dialect numbers itself writes control_alarm, and the schema takes it") {
    dialects::Registry registry = dialects::builtin_registry();
    REQUIRE(registry.add_text("id = \"test-ngc\"\nname = \"Test NGC\"\nbase = \"haas-mill\"\n[alarms]\ncontrol = \"Test NGC\"\n"
                              "program_not_found = { number = 7078, text = \"TEST PROGRAM NOT FOUND\", reference = \"test data\" }\n",
                              "test.toml")
                .empty());
    const test::JsonSchema schema = test::load_schema(kSchema.string());
    for (const char* id : {"test-ngc", "haas-mill"}) {
        INFO(id);
        const dialects::Dialect& d = *registry.find(id);
        interpreter::ProgramSet programs;
        const auto main = programs.first_program(programs.add("t.nc", "O1\nG00 X1. Y1.\nM98 P1234\nM30\n", d));
        REQUIRE(main);
        interpreter::VectorSink sink;
        interpreter::run(programs, *main, d, test::plain_setup(d), sink);
        REQUIRE(!sink.events.empty());
        const test::Event& alarm = sink.events.back();
        REQUIRE(alarm.kind == test::EventKind::alarm);
        const json::object line = interpreter::event_to_json(alarm, programs, "XYZ");
        INFO(json::serialize(line));
        CHECK(schema.validate(line).empty());
        CHECK(line.at("code").as_int64() == 78);
        if (std::string(id) == "test-ngc") {
            CHECK(line.at("control_alarm").as_int64() == 7078);
            CHECK(std::string(line.at("text").as_string()) ==
                  "Test NGC alarm 7078 TEST PROGRAM NOT FOUND: program O1234 not found (FANUC alarm 078)");
        } else if (std::string(id) == "haas-mill") {
            // A control whose numbers kerf does not have (docs/haas.md): FANUC's, said to be FANUC's.
            CHECK_FALSE(line.contains("control_alarm"));
            CHECK(std::string(line.at("text").as_string()) ==
                  "program O1234 not found (FANUC alarm 078) (Haas NGC numbers this alarm its own way; kerf gives FANUC's)");
        } else {
            CHECK_FALSE(line.contains("control_alarm"));
            CHECK(std::string(line.at("text").as_string()) == "program O1234 not found (alarm 078)");
        }
    }
    test::Event a;
    a.kind = test::EventKind::alarm;
    a.code = 78;
    a.control_alarm = 7078;
    test::Event b = a;
    b.control_alarm = 0;
    const interpreter::CompareOptions everything{interpreter::CompareProfile::everything, 1e-9};
    CHECK(interpreter::compare_events(a, b, everything).value_or("").find("control_alarm") == 0);
}

TEST_CASE("--verify compares every field the trace shows: a G34 thread's end lead too") {
    test::Event a;
    a.kind = test::EventKind::thread;
    a.feed = 2;
    a.lead_end = 3;
    test::Event b = a;
    const interpreter::CompareOptions everything{interpreter::CompareProfile::everything, 1e-9};
    CHECK_FALSE(interpreter::compare_events(a, b, everything).has_value());
    b.lead_end = 3.5;
    CHECK(interpreter::compare_events(a, b, everything).value_or("").find("lead_end") == 0);
    b = a;
    b.inch = true;
    CHECK(interpreter::compare_events(a, b, everything).value_or("").find("units") == 0);
    // Texts of alarms quote sequence numbers that renumbering changes: not compared; a message's are.
    a.kind = b.kind = test::EventKind::alarm;
    b = a;
    a.text = "GOTO 10: no N10";
    b.text = "GOTO 20: no N20";
    CHECK_FALSE(interpreter::compare_events(a, b, everything).has_value());
    a.kind = b.kind = test::EventKind::message;
    CHECK(interpreter::compare_events(a, b, everything).value_or("").find("text") == 0);
    // File and line move when a program is formatted: not compared.
    b = a;
    b.source.line = 40;
    CHECK_FALSE(interpreter::compare_events(a, b, everything).has_value());
}
