// Completion, by what the cursor is typing:
//
//   G.. / M..            the dialect's codes with their descriptions (and, after G, snippets for the
//                        two-block cycles in this dialect's G-code system: G71/G72/G73/G76... by
//                        function id, so system C gets G73 for stock removal in turning)
//   P in M98/G65/G66     the programs of this file and of the workspace index
//   Q in M98, P in M99/M97, P/Q in G70–G73, GOTO n    the labels of the program the word refers to
//   #..                  the variables the document uses and the system variables kerf knows
//   a letter, or nothing the words the block's codes take that it does not have yet
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <tuple>

#include "dialects/functions.hpp"
#include "lsp/features/common.hpp"
#include "lsp/features/variables.hpp"

namespace kerf::lsp {

namespace {

namespace fn = dialects::functions;
constexpr std::size_t kMaxLabels = 400;
constexpr std::uint32_t kWindow = 5000;   // blocks each side of the cursor searched for labels

struct Typing {
    std::uint32_t begin = 0;   // the word being typed: [begin, offset)
    std::string text;          // upper case
};

Typing typing_at(const Document& doc, std::uint32_t offset) {
    const std::string& text = doc.text();
    std::uint32_t b = offset;
    while (b > 0) {
        const char c = text[b - 1];
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-')) break;
        --b;
    }
    if (b > 0 && text[b - 1] == '#') --b;   // "X#1": the variable is typed, not the X word
    Typing t{b, std::string(text.substr(b, offset - b))};
    for (char& c : t.text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return t;
}

json::object edit_range(const Document& doc, const Typing& t, std::uint32_t offset) { return range_json(doc, {t.begin, offset}); }

json::object item(std::string label, int kind, std::string detail, const json::object& range, std::string insert) {
    return {{"label", label},
            {"kind", kind},
            {"detail", std::move(detail)},
            {"filterText", label},
            {"textEdit", json::object{{"range", range}, {"newText", std::move(insert)}}}};
}

void codes(const Snapshot& s, char letter, const json::object& range, json::array& out) {
    const FileSettings& settings = s.doc->settings();
    for (const dialects::CodeInfo& c : settings.dialect->codes()) {
        if (c.letter != letter) continue;
        json::object i = item(c.spelling, letter == 'G' ? completion_kind::keyword : completion_kind::function,
                              description(c, settings.language), range, c.spelling);
        std::string doc = c.group == "00" ? "group 00 (one-shot)" : c.group.empty() ? "" : "group " + c.group;
        if (!c.words.empty()) {
            std::string words;
            for (const std::string& w : c.words) words += " " + w;
            doc += (doc.empty() ? "" : " · ") + std::string("words:") + words;
        }
        if (!c.notes.empty()) doc += "\n\n" + c.notes;
        i["documentation"] = json::object{{"kind", "markdown"}, {"value", doc}};
        i["sortText"] = c.spelling;
        out.push_back(std::move(i));
    }
}

// Two-block cycle forms (cycles.md §2–§7), spelled with this dialect's code for the function.
struct CycleSnippet {
    dialects::FunctionId function;
    const char* name;
    const char* body;   // {0} = the code
};
constexpr CycleSnippet kSnippets[] = {
    {fn::rough_turning_cycle, "stock removal in turning, two blocks (cycles.md §2)",
     "{0} U${{1:depth}} R${{2:retract}}\n{0} P${{3:first_N}} Q${{4:last_N}} U${{5:x_allowance}} W${{6:z_allowance}} F${{7:feed}}"},
    {fn::rough_facing_cycle, "stock removal in facing, two blocks (cycles.md §3)",
     "{0} W${{1:depth}} R${{2:retract}}\n{0} P${{3:first_N}} Q${{4:last_N}} U${{5:x_allowance}} W${{6:z_allowance}} F${{7:feed}}"},
    {fn::pattern_repeating_cycle, "pattern repeating, two blocks (cycles.md §4)",
     "{0} U${{1:x_relief}} W${{2:z_relief}} R${{3:passes}}\n{0} P${{4:first_N}} Q${{5:last_N}} U${{6:x_allowance}} W${{7:z_allowance}} F${{8:feed}}"},
    {fn::finishing_cycle, "finishing cycle (cycles.md §1)", "{0} P${{1:first_N}} Q${{2:last_N}}"},
    {fn::multiple_threading_cycle, "multiple threading cycle, two blocks (cycles.md §7)",
     "{0} P${{1:02}}${{2:00}}${{3:60}} Q${{4:min_depth}} R${{5:finish_allowance}}\n{0} X${{6:root_diameter}} Z${{7:end_z}} R${{8:0}} P${{9:height}} Q${{10:first_depth}} F${{11:lead}}"},
    {fn::face_peck_drilling_cycle, "face peck drilling / grooving, two blocks (cycles.md §5)",
     "{0} R${{1:retract}}\n{0} Z${{2:depth}} Q${{3:peck}} F${{4:feed}}"},
    {fn::grooving_cycle, "OD/ID grooving, two blocks (cycles.md §6)",
     "{0} R${{1:retract}}\n{0} X${{2:bottom}} Z${{3:last_z}} P${{4:peck}} Q${{5:shift}} F${{6:feed}}"},
};

void snippets(const Snapshot& s, const json::object& range, json::array& out) {
    for (const CycleSnippet& sn : kSnippets) {
        const auto codes = s.doc->dialect().codes_with_function(sn.function);
        if (codes.empty()) continue;
        const std::string code = codes.front()->spelling;
        json::object i = item(code + " …", completion_kind::snippet, fmt::format("{}: {}", code, sn.name), range,
                              fmt::format(fmt::runtime(sn.body), code));
        i["filterText"] = code;
        i["insertTextFormat"] = 2;
        i["sortText"] = code + "~";
        out.push_back(std::move(i));
    }
}

void programs(const Snapshot& s, const std::string& prefix, const json::object& range, json::array& out) {
    std::set<std::int64_t> seen;
    const auto add = [&](std::int64_t n, std::string detail) {
        if (!seen.insert(n).second) return;
        const std::string label = fmt::format("{}{:04}", prefix, n);
        out.push_back(item(label, completion_kind::module, std::move(detail), range, label));
    };
    for (const IndexedProgram& p : ProjectSeam::programs_of(s.doc->path(), s.doc->typed()))
        add(p.number, p.comment.empty() ? "this file" : p.comment + " (this file)");
    for (const IndexedProgram& p : s.project.all_programs())
        add(p.number, p.comment.empty() ? p.file.filename().string() : fmt::format("{} ({})", p.comment, p.file.filename().string()));
}

void labels(const Snapshot& s, std::uint32_t program, std::uint32_t near, const std::string& prefix, const json::object& range,
            json::array& out) {
    const Document& doc = *s.doc;
    const ast::Program& p = doc.typed().programs()[program];
    // The labels near the cursor (a CAM program numbers every one of a million blocks).
    const std::uint32_t first = std::max(p.first_block, near > kWindow ? near - kWindow : 0);
    const std::uint32_t last = std::min(p.end_block, near + kWindow);
    std::vector<std::tuple<std::uint32_t, std::int64_t, std::uint32_t>> found;   // distance, label, block
    std::set<std::int64_t> seen;
    for (std::uint32_t b = first; b < last; ++b) {
        const auto n = n_word(doc.tree(), b);
        if (!n) continue;
        const auto v = ast::integer_value(doc.tree(), doc.tree().tokens[*n]);
        if (v && seen.insert(*v).second) found.emplace_back(b > near ? b - near : near - b, *v, b);
    }
    std::sort(found.begin(), found.end());
    if (found.size() > kMaxLabels) found.resize(kMaxLabels);
    for (const auto& [distance, label, block] : found) {
        const std::string text = fmt::format("{}{}", prefix, label);
        json::object i = item(text, completion_kind::reference, std::string(clip(doc.tree().slice(words_range(doc.tree(), block)), 60)), range, text);
        i["sortText"] = fmt::format("{:08}", distance);
        out.push_back(std::move(i));
    }
}

void variables(const Snapshot& s, const json::object& range, json::array& out) {
    const ast::SyntaxTree& tree = s.doc->tree();
    std::set<std::int64_t> used;
    for (const ast::Expr& e : tree.exprs) {
        if (e.kind != ast::ExprKind::variable || e.a < 0) continue;
        const ast::Expr& n = tree.exprs[static_cast<std::size_t>(e.a)];
        if (n.kind != ast::ExprKind::number || tree.number_value(n) != std::floor(tree.number_value(n))) continue;
        if (const auto number = ast::truncated_integer(tree.number_value(n))) used.insert(*number);
    }
    const std::string& language = s.doc->settings().language;
    for (const std::int64_t v : used) {
        const std::string label = fmt::format("#{}", v);
        json::object i = item(label, completion_kind::variable, variable_kind(v, language), range, label);
        i["sortText"] = fmt::format("0{:08}", v);
        out.push_back(std::move(i));
    }
    for (const SystemVariable& v : system_variables()) {
        if (used.count(v.first)) continue;
        const std::string label = fmt::format("#{}", v.first);
        json::object i = item(label, completion_kind::variable, language == "ru" ? v.ru : v.en, range, label);
        i["sortText"] = fmt::format("1{:08}", v.first);
        out.push_back(std::move(i));
    }
}

// The letters the block's codes take that the block does not have yet.
void block_words(const Snapshot& s, std::uint32_t block, const json::object& range, json::array& out) {
    const ast::BlockView view = s.doc->typed().block(block);
    std::vector<ast::CodeRef> g, m;
    view.collect_codes(g, m);
    std::set<std::string> offered;
    for (const auto* list : {&g, &m})
        for (const ast::CodeRef& c : *list) {
            if (!c.info) continue;
            for (const std::string& w : c.info->words) {
                if (w.empty() || w[0] == ',' || view.word(w[0]) || !offered.insert(w).second) continue;
                out.push_back(item(w, completion_kind::field, fmt::format("word of {} ({})", c.info->spelling, description(*c.info, s.doc->settings().language)),
                                   range, w));
            }
        }
}

bool has_function(const ast::BlockView& view, std::initializer_list<dialects::FunctionId> functions) {
    std::vector<ast::CodeRef> g, m;
    view.collect_codes(g, m);
    for (const auto* list : {&g, &m})
        for (const ast::CodeRef& c : *list)
            if (c.info && std::find(functions.begin(), functions.end(), c.info->function) != functions.end()) return true;
    return false;
}

}  // namespace

json::value completion(const Snapshot& s, ast::Position at) {
    const Document& doc = s.document();
    json::array items;
    if (!doc.refused().empty()) return json::object{{"isIncomplete", false}, {"items", items}};
    const std::uint32_t offset = doc.offset(at);
    const Typing t = typing_at(doc, offset);
    const json::object range = edit_range(doc, t, offset);
    const std::uint32_t block = doc.block_at(t.begin);
    const auto program = references::program_of_block(doc.typed(), block);
    const ast::BlockView view = doc.typed().block(block);
    // The line before the word: "IF [#1 LT 3] GOTO " asks for a label.
    const std::uint32_t line_start = doc.lines().line_start(doc.lines().utf8(t.begin).line);
    std::string before(doc.text().substr(line_start, t.begin - line_start));
    for (char& c : before) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    while (!before.empty() && before.back() == ' ') before.pop_back();
    const bool after_goto = before.ends_with("GOTO");
    const char letter = t.text.empty() ? 0 : t.text[0];
    bool incomplete = false;

    if (after_goto && program && (t.text.empty() || std::isdigit(static_cast<unsigned char>(letter)))) {
        labels(s, *program, block, "", range, items);
        incomplete = true;
    } else if (letter == '#') {
        variables(s, range, items);
    } else if (letter == 'G') {
        codes(s, 'G', range, items);
        snippets(s, range, items);
    } else if (letter == 'M') {
        codes(s, 'M', range, items);
    } else if ((letter == 'P' || letter == 'Q') && program) {
        const bool call = has_function(view, {fn::subprogram_call, fn::macro_call, fn::modal_macro_call});
        const bool label_p = has_function(view, {fn::subprogram_return, fn::local_subprogram_call, fn::finishing_cycle,
                                                 fn::rough_turning_cycle, fn::rough_facing_cycle, fn::pattern_repeating_cycle});
        if (letter == 'P' && call) {
            programs(s, "P", range, items);
        } else if (letter == 'Q' && has_function(view, {fn::subprogram_call})) {
            // M98 P Q: the called program's labels when it is in this file.
            std::uint32_t target = *program;
            if (const auto call_ref = view.subprogram_call())
                if (const auto p = references::program_numbered(doc.typed(), call_ref->program)) target = *p;
            labels(s, target, block, "Q", range, items);
            incomplete = true;
        } else if (label_p) {
            std::uint32_t target = *program;
            if (has_function(view, {fn::subprogram_return})) {
                const auto callers = references::callers_of(doc.typed(), *program);
                if (!callers.empty()) target = callers.front();
            }
            labels(s, target, block, std::string(1, letter), range, items);
            incomplete = true;
        } else {
            block_words(s, block, range, items);
        }
    } else if (t.text.size() <= 1) {
        block_words(s, block, range, items);
    }
    return json::object{{"isIncomplete", incomplete}, {"items", std::move(items)}};
}

}  // namespace kerf::lsp
