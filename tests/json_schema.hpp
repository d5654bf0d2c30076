// A small JSON Schema validator (draft-07 subset) on Boost.JSON, for the tests that check kerf's
// JSON and SARIF outputs against tests/schemas/sarif-2.1.0.json and docs/check-json.schema.json.
//
// Supported keywords: type (a name or a list), required, properties, additionalProperties (bool or
// schema), items (one schema), enum, const, minimum, maximum, minItems, uniqueItems, pattern,
// $ref (to "#/definitions/<name>" only), oneOf, anyOf, allOf. Annotations are ignored ($schema,
// $id, title, description, default, format, $comment, examples). Any other keyword in a schema
// is reported as an error: a schema never relies silently on a keyword this validator skips.
#pragma once

#include <boost/json.hpp>

#include <string>
#include <vector>

namespace kerf::test {

class JsonSchema {
public:
    explicit JsonSchema(boost::json::value schema) : root_(std::move(schema)) {}

    // One line per violation, "<json pointer>: <what>"; empty when `doc` is valid.
    std::vector<std::string> validate(const boost::json::value& doc) const;

private:
    boost::json::value root_;
};

// Parses the schema file at `path` (REQUIREs that it reads and parses).
JsonSchema load_schema(const std::string& path);

}  // namespace kerf::test
