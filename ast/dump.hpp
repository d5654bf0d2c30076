// Dumps of the typed AST: JSON with ranges (kerf parse --json) and a readable text tree
// (kerf parse, golden tests in tests/golden/ast).
#pragma once

#include <boost/json/value.hpp>
#include <string>

#include "ast/typed.hpp"

namespace kerf::ast {

// A number or expression in prefix form: "(+ #1 2.)", "(ATAN #1 #2)".
std::string expr_to_string(const SyntaxTree& tree, std::int32_t expr);
std::string statement_to_string(const SyntaxTree& tree, std::int32_t statement);

boost::json::value to_json(const TypedFile& file, const LineIndex& lines);
std::string to_text(const TypedFile& file, const LineIndex& lines);
boost::json::value diagnostic_to_json(const Diagnostic& d, const LineIndex& lines);

}  // namespace kerf::ast
