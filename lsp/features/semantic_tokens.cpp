// Semantic tokens (full and range): what each word is by its bound role, not by its letter. Types:
// G codes (modifier: their modal group, "oneShot" for group 00), M codes, axis words ("incremental"
// for U/W in system A), feeds, spindle speeds, tools, N labels, O numbers, macro variables (local /
// common / system), macro keywords, operators and functions, numbers, comments. A document over
// 8 MB gets no full token list (tens of megabytes of JSON for a client that shows a screen): the
// range request colours what is visible.
#include <algorithm>
#include <cctype>
#include <set>

#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

enum Type { gcode, mcode, axis, feed, spindle, tool, label, program, variable, keyword, comment, parameter, number, operator_, function, type_count };
constexpr const char* kTypes[] = {"gcode", "mcode", "axis", "feed", "spindle", "tool", "label", "program", "variable",
                                  "keyword", "comment", "parameter", "number", "operator", "function"};
static_assert(std::size(kTypes) == type_count);
enum Modifier { incremental, local, common, system, deleted, modal, one_shot, fixed_modifiers };
constexpr const char* kModifiers[] = {"incremental", "local", "common", "system", "deleted", "modal", "oneShot"};
constexpr std::size_t kMaxFullBytes = std::size_t{8} << 20;

// The modal groups of every built-in dialect, after the fixed modifiers ("group01" ...), at most 32 in all.
const std::vector<std::string>& group_modifiers() {
    static const std::vector<std::string> groups = [] {
        std::set<std::string> all;
        const dialects::Registry& r = dialects::builtin_registry();
        for (const std::string& id : r.ids())
            for (const dialects::CodeInfo& c : r.find(id)->codes())
                if (!c.group.empty()) all.insert(c.group);
        std::vector<std::string> out;
        for (const std::string& g : all)
            if (out.size() + fixed_modifiers < 32) out.push_back(g);
        return out;
    }();
    return groups;
}

std::uint32_t group_bit(const std::string& group) {
    const auto& groups = group_modifiers();
    const auto it = std::find(groups.begin(), groups.end(), group);
    return it == groups.end() ? 0 : 1u << (fixed_modifiers + (it - groups.begin()));
}

class Encoder {
public:
    explicit Encoder(const Document& doc) : doc_(doc) {}
    void add(std::uint32_t begin, std::uint32_t end, int type, std::uint32_t modifiers = 0) {
        if (end <= begin) return;
        const ast::Position b = doc_.position(begin);
        ast::Position e = doc_.position(end);
        if (e.line != b.line) e = {b.line, b.column + 1};   // tokens never span lines; be safe
        const std::uint32_t delta_line = b.line - line_;
        const std::uint32_t delta_start = delta_line == 0 ? b.column - column_ : b.column;
        for (const std::uint32_t v : {delta_line, delta_start, e.column - b.column, static_cast<std::uint32_t>(type), modifiers})
            data_.push_back(v);
        line_ = b.line;
        column_ = b.column;
    }
    json::array take() { return std::move(data_); }

private:
    const Document& doc_;
    json::array data_;
    std::uint32_t line_ = 0, column_ = 0;
};

std::uint32_t variable_modifier(std::int64_t n) {
    if (n >= 1 && n <= 33) return 1u << local;
    if (n >= 100 && n < 1000) return 1u << common;
    if (n >= 1000) return 1u << system;
    return 0;
}

bool one_of(std::string_view word, std::initializer_list<std::string_view> list) {
    return std::find(list.begin(), list.end(), word) != list.end();
}

// Macro text (a statement, or a word's expression value): variables, keywords, operators,
// functions and numbers by their spelling.
void scan_macro(Encoder& out, std::string_view text, std::uint32_t base) {
    std::size_t i = 0;
    while (i < text.size()) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '#' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1]))) {
            std::size_t j = i + 1;
            std::int64_t n = 0;
            while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) && n < 1000000000) n = n * 10 + (text[j++] - '0');
            out.add(static_cast<std::uint32_t>(base + i), static_cast<std::uint32_t>(base + j), variable, variable_modifier(n));
            i = j;
        } else if (std::isalpha(c)) {
            std::size_t j = i;
            std::string word;
            while (j < text.size() && std::isalpha(static_cast<unsigned char>(text[j])))
                word += static_cast<char>(std::toupper(static_cast<unsigned char>(text[j++])));
            int type = -1;
            if (one_of(word, {"IF", "GOTO", "THEN", "WHILE", "DO", "END", "DPRNT", "BPRNT", "POPEN", "PCLOS"})) type = keyword;
            else if (one_of(word, {"EQ", "NE", "GT", "LT", "GE", "LE", "AND", "OR", "XOR", "MOD"})) type = operator_;
            else if (one_of(word, {"SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "BIN", "BCD", "ROUND", "FIX", "FUP", "LN", "EXP", "POW", "ADP"}))
                type = function;
            if (type >= 0) out.add(static_cast<std::uint32_t>(base + i), static_cast<std::uint32_t>(base + j), type);
            i = j;
        } else if (std::isdigit(c) || (c == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
            std::size_t j = i;
            while (j < text.size() && (std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.')) ++j;
            out.add(static_cast<std::uint32_t>(base + i), static_cast<std::uint32_t>(base + j), number);
            i = j;
        } else {
            ++i;
        }
    }
}

int word_type(const ast::Token& t, std::uint32_t& modifiers) {
    switch (t.role()) {
        case ast::Role::g_code: return gcode;
        case ast::Role::m_code: return mcode;
        case ast::Role::sequence: return label;
        case ast::Role::program: return program;
        case ast::Role::axis_absolute: return axis;
        case ast::Role::axis_incremental: modifiers |= 1u << incremental; return axis;
        case ast::Role::direct_drawing: return parameter;
        default: break;
    }
    switch (t.letter) {
        case 'F': return feed;
        case 'S': return spindle;
        case 'T': return tool;
        default: return parameter;
    }
}

void block_tokens(const Document& doc, std::uint32_t block, Encoder& out) {
    const ast::SyntaxTree& tree = doc.tree();
    const bool deleted_block = tree.blocks[block].has(ast::block_flags::deleted);
    for (std::uint32_t i = tree.block_first_token(block); i < tree.block_token_end(block); ++i) {
        const ast::Token& t = tree.tokens[i];
        const std::uint32_t base = deleted_block ? 1u << deleted : 0;
        switch (t.kind) {
            case ast::TokenKind::word: {
                std::uint32_t modifiers = base;
                const int type = word_type(t, modifiers);
                if (type == gcode && t.is_number())
                    if (const auto key = dialects::code_key(tree.number_value(t)))
                        if (const dialects::CodeInfo* info = doc.dialect().code(t.letter, *key))
                            modifiers |= group_bit(info->group) | (info->group == "00" ? 1u << one_shot : info->modal ? 1u << modal : 0);
                if (t.has(ast::token_flags::value_expr)) {
                    out.add(t.begin, t.begin + 1, type, modifiers);
                    scan_macro(out, tree.spelling(t).substr(1), t.begin + 1);
                } else {
                    out.add(t.begin, tree.end(t), type, modifiers);
                }
                break;
            }
            case ast::TokenKind::comma_word: out.add(t.begin, tree.end(t), parameter, base); break;
            case ast::TokenKind::comment: out.add(t.begin, tree.end(t), comment, base); break;
            case ast::TokenKind::statement: {
                // DPRNT[...] / BPRNT[...] hold text and formats, not an expression.
                std::string head(tree.spelling(t).substr(0, 5));
                for (char& c : head) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
                if (head == "DPRNT" || head == "BPRNT") out.add(t.begin, t.begin + 5, keyword, base);
                else scan_macro(out, tree.spelling(t), t.begin);
                break;
            }
            case ast::TokenKind::block_delete:
            case ast::TokenKind::percent: out.add(t.begin, tree.end(t), keyword, base); break;
            case ast::TokenKind::eob: out.add(t.begin, tree.end(t), operator_, base); break;
            default: break;
        }
    }
}

}  // namespace

json::object semantic_tokens_legend() {
    json::array types, modifiers;
    for (const char* t : kTypes) types.push_back(json::string(t));
    for (const char* m : kModifiers) modifiers.push_back(json::string(m));
    for (const std::string& g : group_modifiers()) modifiers.push_back(json::string("group" + g));
    return {{"tokenTypes", std::move(types)}, {"tokenModifiers", std::move(modifiers)}};
}

json::value semantic_tokens(const Snapshot& s, std::optional<std::pair<ast::Position, ast::Position>> range) {
    const Document& doc = s.document();
    Encoder out(doc);
    if (!doc.refused().empty() || (!range && doc.text().size() > kMaxFullBytes)) return json::object{{"data", json::array{}}};
    std::uint32_t first = 0, last = static_cast<std::uint32_t>(doc.tree().block_count());
    if (range) {
        first = doc.block_at(doc.offset(range->first));
        last = std::min<std::uint32_t>(last, doc.block_at(doc.offset(range->second)) + 1);
    }
    for (std::uint32_t b = first; b < last; ++b) block_tokens(doc, b, out);
    return json::object{{"data", out.take()}};
}

}  // namespace kerf::lsp
