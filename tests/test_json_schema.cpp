// The JSON Schema validator of the tests (tests/json_schema.hpp): each keyword accepts what it
// should and rejects a wrong document, so a passing schema test means something.
#include <catch2/catch.hpp>

#include "tests/json_schema.hpp"

namespace json = boost::json;
using kerf::test::JsonSchema;

namespace {

std::vector<std::string> errors_of(const char* schema, const char* doc) {
    return JsonSchema(json::parse(schema)).validate(json::parse(doc));
}

bool valid(const char* schema, const char* doc) { return errors_of(schema, doc).empty(); }

}  // namespace

TEST_CASE("json schema: type, with integer as a number without fraction") {
    CHECK(valid(R"({"type":"integer"})", "3"));
    CHECK(valid(R"({"type":"integer"})", "3.0"));
    CHECK_FALSE(valid(R"({"type":"integer"})", "3.5"));
    CHECK_FALSE(valid(R"({"type":"integer"})", "\"3\""));
    CHECK(valid(R"({"type":"number"})", "3.5"));
    CHECK(valid(R"({"type":["array","null"]})", "null"));
    CHECK_FALSE(valid(R"({"type":["array","null"]})", "{}"));
    CHECK_FALSE(valid(R"({"type":"boolean"})", "0"));
}

TEST_CASE("json schema: required, properties, additionalProperties") {
    const char* schema = R"({"type":"object","required":["a"],"properties":{"a":{"type":"string"}},
                            "additionalProperties":false})";
    CHECK(valid(schema, R"({"a":"x"})"));
    CHECK_FALSE(valid(schema, R"({})"));
    CHECK_FALSE(valid(schema, R"({"a":1})"));
    const std::vector<std::string> extra = errors_of(schema, R"({"a":"x","b":1})");
    REQUIRE(extra.size() == 1);
    CHECK(extra[0] == ": property 'b' is not allowed");
    // additionalProperties as a schema checks the members `properties` does not name.
    const char* map = R"({"properties":{"n":{"type":"integer"}},"additionalProperties":{"type":"string"}})";
    CHECK(valid(map, R"({"n":1,"x":"y"})"));
    CHECK_FALSE(valid(map, R"({"n":1,"x":2})"));
}

TEST_CASE("json schema: items, minItems, uniqueItems with the path of the bad item") {
    const char* schema = R"({"type":"array","items":{"type":"integer","minimum":1},"minItems":1,"uniqueItems":true})";
    CHECK(valid(schema, "[1,2]"));
    CHECK_FALSE(valid(schema, "[]"));
    CHECK_FALSE(valid(schema, "[1,1]"));
    const std::vector<std::string> e = errors_of(schema, "[1,0]");
    REQUIRE(e.size() == 1);
    CHECK(e[0] == "/1: 0 is less than 1");
}

TEST_CASE("json schema: enum, const, minimum, maximum, pattern") {
    CHECK(valid(R"({"enum":["none","note","warning","error"]})", R"("note")"));
    CHECK_FALSE(valid(R"({"enum":["none","note","warning","error"]})", R"("info")"));
    CHECK(valid(R"({"const":"2.1.0"})", R"("2.1.0")"));
    CHECK_FALSE(valid(R"({"const":"2.1.0"})", R"("2.1")"));
    CHECK_FALSE(valid(R"({"maximum":100})", "101"));
    CHECK(valid(R"({"pattern":"^K[0-9]{4}$"})", R"("K1001")"));
    CHECK_FALSE(valid(R"({"pattern":"^K[0-9]{4}$"})", R"("K101")"));
}

TEST_CASE("json schema: $ref to definitions, oneOf, anyOf, allOf") {
    const char* schema = R"({"definitions":{"pos":{"type":"integer","minimum":1}},
                            "properties":{"line":{"$ref":"#/definitions/pos"}}})";
    CHECK(valid(schema, R"({"line":1})"));
    const std::vector<std::string> e = errors_of(schema, R"({"line":0})");
    REQUIRE(e.size() == 1);
    CHECK(e[0] == "/line: 0 is less than 1");
    CHECK_FALSE(valid(R"({"$ref":"#/definitions/missing"})", "1"));
    const char* one = R"({"oneOf":[{"type":"integer"},{"type":"number"}]})";
    CHECK(valid(one, "1.5"));
    CHECK_FALSE(valid(one, "1"));   // both match
    const char* any = R"({"anyOf":[{"required":["text"]},{"required":["id"]}]})";
    CHECK(valid(any, R"({"id":"x"})"));
    CHECK_FALSE(valid(any, R"({"markdown":"x"})"));
    CHECK_FALSE(valid(R"({"allOf":[{"type":"integer"},{"minimum":2}]})", "1"));
}

TEST_CASE("json schema: a keyword the validator does not know is an error, annotations are not") {
    CHECK(valid(R"({"description":"d","format":"uri","default":1,"title":"t"})", "1"));
    const std::vector<std::string> e = errors_of(R"({"maxLength":2})", R"("abc")");
    REQUIRE(e.size() == 1);
    CHECK(e[0] == ": (schema) unsupported keyword 'maxLength'");
}
