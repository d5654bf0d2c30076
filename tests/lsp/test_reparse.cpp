// The document store's incremental re-parse (lsp/reparse.hpp, ast::TypedFile::bind_edited): after
// any edit the tree, the token roles, the programs and the diagnostics must be exactly those of a
// parse and bind of the whole new text. Checked on every reference example and corpus file under
// the dialect detected for it, with edits drawn by a fixed-seed generator (typing, deleting across
// lines, pasting lines, typing and deleting '%', which changes how the rest of the file reads),
// and on hand-made cases with UTF-16 positions.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <string>

#include "grammar/detect.hpp"
#include "grammar/parse.hpp"
#include "lsp/document.hpp"
#include "lsp/reparse.hpp"
#include "tests/lsp/random_edits.hpp"
#include "tests/shared_files.hpp"

using namespace kerf;

namespace {

double token_number(const ast::SyntaxTree& t, const ast::Token& tok) { return tok.is_number() ? t.number_value(tok) : 0; }

// The first difference between two trees, "" when there is none. Everything is compared but the
// index of a big number (the incremental tree appends new ones): their values are.
std::string difference(const ast::SyntaxTree& a, const ast::SyntaxTree& b) {
#define KERF_SAME(what, x, y) \
    do {                      \
        if (!((x) == (y))) return std::string(what) + " " + std::to_string(i); \
    } while (0)
    std::size_t i = 0;
    if (a.text != b.text) return "text";
    if (a.blocks.size() != b.blocks.size()) return "block count " + std::to_string(a.blocks.size()) + " vs " + std::to_string(b.blocks.size());
    for (i = 0; i < a.blocks.size(); ++i) {
        KERF_SAME("block begin", a.blocks[i].begin, b.blocks[i].begin);
        KERF_SAME("block first token", a.blocks[i].first_token, b.blocks[i].first_token);
        KERF_SAME("block kind", a.blocks[i].kind, b.blocks[i].kind);
        KERF_SAME("block flags", a.blocks[i].flags, b.blocks[i].flags);
    }
    if (a.tokens.size() != b.tokens.size()) return "token count";
    if (a.long_tokens.size() != b.long_tokens.size()) return "long token count";
    for (i = 0; i < a.tokens.size(); ++i) {
        const ast::Token &x = a.tokens[i], &y = b.tokens[i];
        KERF_SAME("token begin", x.begin, y.begin);
        KERF_SAME("token length", a.length(x), b.length(y));
        KERF_SAME("token kind", x.kind, y.kind);
        KERF_SAME("token letter", x.letter, y.letter);
        KERF_SAME("token flags", x.flags, y.flags);
        KERF_SAME("token role", x.role(), y.role());   // the role the binder gave it
        if (x.has(ast::token_flags::value_big)) KERF_SAME("token big value", token_number(a, x), token_number(b, y));
        else if (x.payload != y.payload)
            return "token payload " + std::to_string(i) + " '" + std::string(a.spelling(x)) + "' kind " + std::to_string(int(x.kind)) +
                   " flags " + std::to_string(x.flags) + ": " + std::to_string(x.payload) + " vs " + std::to_string(y.payload);
    }
    if (a.exprs.size() != b.exprs.size()) return "expression count";
    for (i = 0; i < a.exprs.size(); ++i) {
        const ast::Expr &x = a.exprs[i], &y = b.exprs[i];
        KERF_SAME("expr begin", x.begin, y.begin);
        KERF_SAME("expr end", x.end, y.end);
        KERF_SAME("expr kind", x.kind, y.kind);
        KERF_SAME("expr op", x.op, y.op);
        KERF_SAME("expr flags", x.flags, y.flags);
        KERF_SAME("expr scale", x.scale, y.scale);
        if (x.kind == ast::ExprKind::number && (x.flags & ast::token_flags::value_big)) KERF_SAME("expr big value", a.number_value(x), b.number_value(y));
        else KERF_SAME("expr a", x.a, y.a);
        KERF_SAME("expr b", x.b, y.b);
    }
    if (a.statements.size() != b.statements.size()) return "statement count";
    for (i = 0; i < a.statements.size(); ++i) {
        const ast::Statement &x = a.statements[i], &y = b.statements[i];
        KERF_SAME("statement range", x.range, y.range);
        KERF_SAME("statement kind", x.kind, y.kind);
        KERF_SAME("statement target", x.target, y.target);
        KERF_SAME("statement value", x.value, y.value);
        KERF_SAME("statement label", x.label, y.label);
        KERF_SAME("statement then", x.then_statement, y.then_statement);
        KERF_SAME("statement text", x.text, y.text);
    }
    if (a.diagnostics.size() != b.diagnostics.size()) return "diagnostic count";
    for (i = 0; i < a.diagnostics.size(); ++i) {
        KERF_SAME("diagnostic range", a.diagnostics[i].range, b.diagnostics[i].range);
        KERF_SAME("diagnostic code", a.diagnostics[i].code, b.diagnostics[i].code);
        KERF_SAME("diagnostic message", a.diagnostics[i].message, b.diagnostics[i].message);
    }
#undef KERF_SAME
    return {};
}

std::vector<std::string> sorted_diagnostics(const ast::TypedFile& f) {
    std::vector<std::string> out;
    for (const ast::Diagnostic& d : f.diagnostics()) out.push_back(std::to_string(d.range.begin) + ":" + d.code + ":" + d.message);
    std::sort(out.begin(), out.end());
    return out;
}

bool same_typed(const ast::TypedFile& a, const ast::TypedFile& b) {
    if (a.programs().size() != b.programs().size()) return false;
    for (std::size_t i = 0; i < a.programs().size(); ++i) {
        const ast::Program &x = a.programs()[i], &y = b.programs()[i];
        if (x.number != y.number || x.first_block != y.first_block || x.end_block != y.end_block || x.o_token != y.o_token) return false;
    }
    return sorted_diagnostics(a) == sorted_diagnostics(b);
}

// The tree on the heap: the typed file points at it, and a Bound is moved around.
struct Bound {
    std::unique_ptr<ast::SyntaxTree> owned;
    std::unique_ptr<ast::TypedFile> typed;
    const ast::SyntaxTree& tree() const { return *owned; }
};

Bound full(const std::string& text, const dialects::Dialect& d) {
    Bound b{std::make_unique<ast::SyntaxTree>(grammar::parse(text, d.lexical)), nullptr};
    b.typed = std::make_unique<ast::TypedFile>(ast::TypedFile::bind(*b.owned, d));
    return b;
}

// Applies `edit` incrementally to `current` and checks it against a whole parse; returns the new state.
Bound step(const Bound& current, const lsp::ByteEdit& edit, const dialects::Dialect& d) {
    ast::BlockSplice splice;
    Bound next{std::make_unique<ast::SyntaxTree>(lsp::reparse(current.tree(), edit, d.lexical, splice)), nullptr};
    next.typed = std::make_unique<ast::TypedFile>(splice.old_end == 0xFFFFFFFFu ? ast::TypedFile::bind(*next.owned, d)
                                                                                 : ast::TypedFile::bind_edited(*next.owned, *current.typed, splice));
    const Bound expected = full(next.tree().text, d);
    REQUIRE(difference(next.tree(), expected.tree()) == "");
    // The document store's path when it is the only holder: the same edit made to the tree itself.
    ast::SyntaxTree in_place = current.tree();
    ast::BlockSplice in_place_splice;
    lsp::reparse_in_place(in_place, edit, d.lexical, in_place_splice);
    const ast::TypedFile in_place_typed = in_place_splice.old_end == 0xFFFFFFFFu ? ast::TypedFile::bind(in_place, d)
                                                                                 : ast::TypedFile::bind_edited(in_place, *current.typed, in_place_splice);
    REQUIRE(difference(in_place, expected.tree()) == "");
    REQUIRE(same_typed(in_place_typed, *expected.typed));
    REQUIRE((in_place_splice.first == splice.first && in_place_splice.removed == splice.removed &&
             in_place_splice.added == splice.added && in_place_splice.old_end == splice.old_end));
    REQUIRE(same_typed(*next.typed, *expected.typed));
    return next;
}

}  // namespace

TEST_CASE("incremental re-parse equals a whole parse after every edit, on every example and corpus file") {
    std::size_t files = 0, edits = 0;
    for (const auto& path : test::shared_files_or_warn("no incremental re-parse sweep")) {
        const std::string text = test::read_text(path);
        if (text.find('\0') != std::string::npos) continue;   // the server does not parse binary files
        const dialects::Dialect* d = dialects::builtin_registry().find(grammar::detect_dialect(text).dialect);
        REQUIRE(d != nullptr);
        INFO(path.filename().string() << " as " << d->id);
        std::mt19937 rng(static_cast<std::uint32_t>(text.size()));
        Bound current = full(text, *d);
        for (int i = 0; i < 12; ++i) {
            std::string storage;
            const lsp::ByteEdit e = test::random_edit(current.tree().text, rng, storage);
            INFO("edit " << i << ": [" << e.begin << ", " << e.end << ") -> '" << e.text << "'");
            current = step(current, e, *d);
            ++edits;
        }
        ++files;
    }
    if (files) CHECK(edits == files * 12);
}

TEST_CASE("incremental re-parse: the cases that change how the rest of the file reads") {
    const dialects::Dialect& d = *dialects::builtin_registry().find("fanuc-mill");
    const auto run = [&](const std::string& text, std::uint32_t begin, std::uint32_t end, const std::string& insert) {
        const Bound b = full(text, d);
        return step(b, {begin, end, insert}, d);
    };
    // A closing '%' typed: the rest becomes the tail the control does not read.
    Bound b = run("%\nO1\nG0 X1\nG1 X2\nM30\n", 11, 11, "%\n");   // before "G1 X2"
    CHECK(b.tree().blocks.back().kind == ast::BlockKind::tail);
    // ...and deleted again: the tail is program text once more.
    b = step(b, {11, 13, ""}, d);
    CHECK(b.tree().blocks.back().kind != ast::BlockKind::tail);
    // An edit inside the tail keeps it one block.
    b = run("%\nO1\nM30\n%\nanything (\nmore\n", 16, 16, "X");
    CHECK(b.tree().blocks.back().kind == ast::BlockKind::tail);
    // Joining two lines, splitting one, the first and the last line, an empty result.
    run("G0 X1\nG1 Y2\n", 5, 6, "");
    run("G0 X1 G1 Y2\n", 6, 6, "\n");
    run("G0 X1\nG1 Y2", 11, 11, "\nM30");
    run("\xEF\xBB\xBFG0 X1\n", 3, 3, "N5 ");
    run("G0 X1\n", 0, 6, "");
    run("", 0, 0, "G0 X1\n");
    run("G0 X#1\n#1=[1+2]*3\nIF [#1 GT 2] GOTO 10\n", 7, 11, "#2");   // expressions and statements renumbered
}

TEST_CASE("incremental re-parse: long tokens (their lengths in the tree) before, inside and after the edit") {
    const dialects::Dialect& d = *dialects::builtin_registry().find("fanuc-mill");
    const std::string comment = "(" + std::string(300, 'C') + ")";
    const std::string expression = "X[" + std::string(150, '1') + "+#1*" + std::string(150, '2') + "]";
    const std::string text = "%\nO1\n" + comment + "\nG1 " + expression + "\n#100=[" + std::string(280, '7') + "]\nG1 X2 " +
                             comment + "\nM30\n%\n";
    const auto at = [&](const std::string& what, std::size_t from = 0) { return static_cast<std::uint32_t>(text.find(what, from)); };
    const Bound b = full(text, d);
    REQUIRE(b.tree().long_tokens.size() == 4);
    // An edit in the middle: the long tokens after it move, those before it stay.
    Bound after = step(b, {at("G1 X2"), at("G1 X2") + 5, "G0 X12345"}, d);
    CHECK(after.tree().long_tokens.size() == 4);
    // The long expression shortened below the limit, then a comment made long by an insertion.
    after = step(after, {at("+#1*") - 100, at("+#1*"), ""}, d);
    CHECK(after.tree().long_tokens.size() == 3);
    after = step(after, {at("("), at("("), "(" + std::string(260, 'y') + ")\n"}, d);
    CHECK(after.tree().long_tokens.size() == 4);
}

TEST_CASE("Document::edit takes LSP positions in UTF-16 units and re-parses only the touched lines") {
    using namespace kerf::lsp;
    auto settings = std::make_shared<FileSettings>();
    settings->registry = std::shared_ptr<const dialects::Registry>(&dialects::builtin_registry(), [](const dialects::Registry*) {});
    settings->dialect = settings->registry->find("fanuc-mill");
    // "Ф" is 2 bytes and 1 UTF-16 unit, "𝄞" 4 bytes and 2 units.
    std::string text = "(ФРЕЗА 𝄞) G0 X1\n";
    for (int i = 0; i < 1000; ++i) text += "N" + std::to_string(i + 1) + " G1 X" + std::to_string(i) + ". F100.\n";
    const auto doc = Document::open("file:///t.nc", "/t.nc", 1, text, settings);
    std::vector<std::string> problems;
    // Replace "X1" on line 0: UTF-16 columns 14..16 ("(ФРЕЗА 𝄞) " is 11 units: ( Ф Р Е З А space,
    // 𝄞 as two, ) space; then "G0 " 3).
    const auto next = doc->edit(2, {ContentChange{std::make_pair(ast::Position{0, 14}, ast::Position{0, 16}), "Y7"}}, problems);
    CHECK(problems.empty());
    CHECK(next->text().substr(0, next->text().find('\n')) == "(ФРЕЗА 𝄞) G0 Y7");
    CHECK(next->reparsed_blocks() == 1);   // one line of 1001
    CHECK(next->version() == 2);
    // A column past the end of a line means its end (LSP 3.17 Position).
    const auto appended = next->edit(3, {ContentChange{std::make_pair(ast::Position{1, 500}, ast::Position{1, 500}), " M8"}}, problems);
    CHECK(appended->text().find("N1 G1 X0. F100. M8\n") != std::string::npos);
    // Two changes in one notification apply in order, each to the text the previous one left.
    const auto two = doc->edit(4, {ContentChange{std::make_pair(ast::Position{1, 0}, ast::Position{1, 3}), ""},
                                   ContentChange{std::make_pair(ast::Position{1, 0}, ast::Position{1, 2}), "G0"}}, problems);
    CHECK(two->text().find("\nG0 X0. F100.\n") != std::string::npos);
    // Outside the document: skipped, said, the text unchanged.
    const auto same = doc->edit(5, {ContentChange{std::make_pair(ast::Position{5000, 0}, ast::Position{5001, 0}), "X"}}, problems);
    CHECK(problems.size() == 1);
    CHECK(same->text() == doc->text());
}

TEST_CASE("Document::edit of the only holder edits that version in place; a shared version is copied") {
    using namespace kerf::lsp;
    auto settings = std::make_shared<FileSettings>();
    settings->registry = std::shared_ptr<const dialects::Registry>(&dialects::builtin_registry(), [](const dialects::Registry*) {});
    settings->dialect = settings->registry->find("fanuc-mill");
    std::string text = "O1\n";
    for (int i = 0; i < 100; ++i) text += "N" + std::to_string(i + 1) + " G1 X" + std::to_string(i) + ". F100.\n";
    std::vector<std::string> problems;
    std::shared_ptr<const Document> doc = Document::open("file:///t.nc", "/t.nc", 1, text, settings);
    const Document* const address = doc.get();
    // Line 2 is "N2 G1 X1. F100.": X1. -> X17. (column 8 is after "X1").
    doc = Document::edit(std::move(doc), 2, {ContentChange{std::make_pair(ast::Position{2, 8}, ast::Position{2, 8}), "7"}}, problems);
    CHECK(doc.get() == address);
    CHECK(doc->version() == 2);
    CHECK(doc->reparsed_blocks() == 1);
    const std::string expected_text = doc->text();
    CHECK(expected_text.find("\nN2 G1 X17. F100.\n") != std::string::npos);
    // The tree and the typed file are those of a whole parse of the new text.
    const auto whole = Document::open("file:///u.nc", "/u.nc", 2, expected_text, settings);
    CHECK(difference(doc->tree(), whole->tree()) == "");
    CHECK(same_typed(doc->typed(), whole->typed()));
    // Another holder (an analysis still running on version 2): version 3 is a new object, 2 unchanged.
    const std::shared_ptr<const Document> held = doc;
    const auto next = Document::edit(doc, 3, {ContentChange{std::make_pair(ast::Position{2, 0}, ast::Position{2, 2}), "N9"}}, problems);
    CHECK(next.get() != held.get());
    CHECK(held->text() == expected_text);
    CHECK(next->text().find("\nN9 G1 X17. F100.\n") != std::string::npos);
    CHECK(problems.empty());
}
