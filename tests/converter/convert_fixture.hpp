// What the converter's tests share: a text converted between two built-in dialects (bound the way
// the project layer binds it), the two dry runs compared motion for motion on one machine
// description (the source dialect's built-in machine, each side in its own dialect's reading), and
// the comments and N numbers of a text.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ast/typed.hpp"
#include "converter/convert.hpp"
#include "dialects/dialect.hpp"
#include "grammar/parse.hpp"
#include "interpreter/default_setup.hpp"
#include "interpreter/trace_compare.hpp"
#include "machine/machine.hpp"

namespace kerf::test {

inline const dialects::Dialect& dialect(const std::string& id) {
    const dialects::Dialect* d = dialects::builtin_registry().find(id);
    if (!d) throw std::runtime_error("unknown dialect " + id);
    return *d;
}

// The source dialect's built-in machine read in `as`'s reading (project::Project::setup(d, machine_of)).
inline interpreter::Setup machine_setup(const dialects::Dialect& machine_of, const dialects::Dialect& as) {
    return interpreter::make_setup(machine::resolve_for_dialect(machine::default_machine_for(machine_of), as));
}

struct Converted {
    std::string text;
    std::vector<converter::Report> reports;
    bool clean = false;
};

inline Converted convert_text(const std::string& text, const dialects::Dialect& from, const dialects::Dialect& to,
                              converter::Options options = {}) {
    ast::SyntaxTree tree = grammar::parse(text, from.lexical);
    const ast::TypedFile typed = ast::TypedFile::bind(tree, from);
    const interpreter::Setup source = machine_setup(from, from), target = machine_setup(from, to);
    if (!options.from) options.from = converter::reading_of(from, source);
    if (!options.to) options.to = converter::reading_of(to, target);
    if (!options.setup) options.setup = source;
    const converter::Conversion c = converter::convert(typed, to, options);
    return {converter::apply(tree.text, c.edits), c.reports, c.clean()};
}

// The first motion difference between `input` in `from` and `output` in `to` (0.001 mm).
inline std::optional<interpreter::TraceDifference> motion_difference(const std::string& input, const dialects::Dialect& from,
                                                                     const std::string& output, const dialects::Dialect& to,
                                                                     const dialects::Dialect* machine_of = nullptr) {
    const dialects::Dialect& m = machine_of ? *machine_of : from;
    interpreter::Setup a = machine_setup(m, from), b = machine_setup(m, to);
    a.step_limit = b.step_limit = 200'000;
    interpreter::TraceSide before{"input.nc", input, &from, a, {}};
    interpreter::TraceSide after{"output.nc", output, &to, b, {}};
    interpreter::CompareOptions o;
    o.profile = interpreter::CompareProfile::motion;
    o.tolerance = 0.001;
    return interpreter::compare_runs(before, after, o).difference;
}

// Every comment's text and every N word of a text, in order.
inline std::vector<std::string> comments_and_numbers(const std::string& text, const dialects::Dialect& d) {
    const ast::SyntaxTree tree = grammar::parse(text, d.lexical);
    std::vector<std::string> out;
    for (const ast::Token& t : tree.tokens) {
        if (t.kind == ast::TokenKind::comment) {
            std::string_view s = tree.spelling(t);
            // The text inside the comment's marks: "(A)" and ";A" are the same comment.
            if (!s.empty() && s.front() == '(') s = s.substr(1, s.size() - (s.back() == ')' ? 2 : 1));
            else
                for (const std::string_view open : {"::", ";;", ";"})
                    if (s.substr(0, open.size()) == open) {
                        s.remove_prefix(open.size());
                        break;
                    }
            std::string c(s);
            // The header names the dialect: the converter renames it on purpose.
            if (const std::size_t at = c.find("DIALECT:"); at != std::string::npos) c = c.substr(0, at + 8);
            while (!c.empty() && (c.back() == ' ' || c.back() == '\t')) c.pop_back();
            for (char& ch : c)
                if (ch == '(') ch = '[';
                else if (ch == ')') ch = ']';
            out.push_back("comment " + c);
        } else if (t.kind == ast::TokenKind::word && t.letter == 'N') {
            out.push_back(std::string(tree.spelling(t)));
        }
    }
    return out;
}

}  // namespace kerf::test
