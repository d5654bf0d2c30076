// Dialect rules: what the dialect table says about codes and words (dialects/SCHEMA.md).
#include <algorithm>
#include <map>
#include <set>

#include "analyzer/rules/common.hpp"
#include "dialects/alarms.hpp"

namespace kerf::analyzer::rules {

namespace {

using S = Severity;
namespace fn = dialects::functions;

template <class F>
void for_codes(const BlockContext& b, F&& f) {
    for (const auto* codes : {&b.g, &b.m})
        for (const ast::CodeRef& c : *codes) f(c);
}

// A G code the dialect does not have: alarm 010 (improper G code). M codes are not G codes: an M
// code the table lacks is left to the machine builder's PMC (K2010/K2011 below).
class UnknownCode : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        for (const ast::CodeRef& c : b.g) {
            if (c.info || !c.key) continue;
            const ast::Token& t = b.token(c.token);
            out.report(b.tree().range(t), fmt::format("{} is not a code of {} ({})", b.tree().spelling(t), b.file.dialect.id,
                                              b.file.dialect.alarms.name_of(alarms::improper_command)),
                       "check the code number, or choose the dialect of the machine (--dialect)");
        }
    }
};

// M codes the dialect's table does not list: a machine builder's code (coolant, clamps, probe
// macro calls). The control passes them to the machine's PMC, it raises no alarm 010. Without a
// list of the machine's M codes: one note per file naming them all (K2010); with the machine file's
// list (m_codes), a warning for each code of neither list, once per file (K2011: the machine does
// not have it).
class UnlistedMCode : public StaticCheck {
public:
    explicit UnlistedMCode(bool machine_list) : machine_list_(machine_list) {}
    void block(const BlockContext& b, Reporter& out) override {
        const std::vector<int>& listed = b.file.setup.m_codes;
        if (listed.empty() == machine_list_ || (!machine_list_ && noted_)) return;   // K2010 without a machine list, K2011 with one
        for (const ast::CodeRef& c : b.m) {
            const auto number = unlisted(c, listed);
            if (!number || std::find(seen_.begin(), seen_.end(), *number) != seen_.end()) continue;
            const ast::Token& t = b.token(c.token);
            if (!machine_list_) {
                note(b.file, b.tree().range(t), out);
                return;
            }
            seen_.push_back(*number);
            out.report(b.tree().range(t), fmt::format("{} is neither in the table of {} nor among the machine's M codes (machine file m_codes)",
                                              b.tree().spelling(t), b.file.dialect.id),
                       "check the code number, or add it to the machine file's m_codes");
        }
    }
    void state(StateKey& key) const override {
        key.add(noted_);
        for (const int number : seen_) key.add(number);
    }

private:
    // The M code number of a code the dialect does not list and the machine file does not either.
    static std::optional<int> unlisted(const ast::CodeRef& c, const std::vector<int>& listed) {
        if (c.info || !c.key || *c.key % 10 != 0) return std::nullopt;
        const int number = *c.key / 10;
        if (std::find(listed.begin(), listed.end(), number) != listed.end()) return std::nullopt;
        return number;
    }
    // K2010: one note for the file at its first unlisted M code, naming every unlisted code of the
    // file where it is first used (M words are among the facts incremental checking digests, so an
    // edit that changes them walks the file whole).
    void note(const FileContext& file, ast::Range at, Reporter& out) {
        noted_ = true;
        std::map<int, ast::Range> first;
        std::vector<ast::CodeRef> g, m;
        for (std::uint32_t i = 0; i < file.tree().block_count(); ++i) {
            if (file.tree().blocks[i].kind != ast::BlockKind::code) continue;
            file.typed.block(i).collect_codes(g, m);
            for (const ast::CodeRef& c : m)
                if (const auto number = unlisted(c, file.setup.m_codes)) first.try_emplace(*number, file.tree().range(file.tree().tokens[c.token]));
        }
        std::string codes;
        for (const auto& [number, where] : first) codes += fmt::format("{}M{:02}", codes.empty() ? "" : ", ", number);
        Finding& f = out.report(at,
                                fmt::format("{} {} not in the table of {}: {} machine builder's M code{}?", codes,
                                            first.size() == 1 ? "is" : "are", file.dialect.id, first.size() == 1 ? "a" : "the",
                                            first.size() == 1 ? "" : "s"),
                                "list the machine's own M codes in its machine file (m_codes), or use the dialect of the machine");
        for (const auto& [number, where] : first) f.related.push_back({where, fmt::format("M{:02} first here", number)});
    }
    bool machine_list_;
    bool noted_ = false;      // K2010: the file's note is made
    std::vector<int> seen_;   // K2011: the codes reported in this file
};
struct UnlistedMCodeNote : UnlistedMCode {
    UnlistedMCodeNote() : UnlistedMCode(false) {}
};
struct MCodeNotOnMachine : UnlistedMCode {
    MCodeNotOnMachine() : UnlistedMCode(true) {}
};

class NotFitted : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        for_codes(b, [&](const ast::CodeRef& c) {
            if (!c.info) return;
            const dialects::Availability a = c.info->availability;
            if (a != dialects::Availability::not_fitted && a != dialects::Availability::optional) return;
            const ast::Token& t = b.token(c.token);
            out.report(b.tree().range(t), fmt::format("{} ({}) is {} on this control", b.tree().spelling(t), c.info->en,
                                              a == dialects::Availability::optional ? "an option" : "not fitted"),
                       c.info->availability_note.empty() ? "remove it or use a machine that has the option"
                                                         : c.info->availability_note);
        });
    }
};

// Letters every block may hold whatever its codes (dialects.md §3.1): they are not code data.
constexpr std::string_view kFreeLetters = "NOGMFSTDHE";

std::set<char> allowed_letters(const BlockContext& b, bool& restricted) {
    std::set<char> letters;
    restricted = false;
    for (const ast::CodeRef& c : b.g) {
        if (!c.info || c.info->group != "00" || c.info->words.empty()) continue;
        restricted = true;
        for (const std::string& w : c.info->words)
            if (w.size() == 1) letters.insert(w[0]);
    }
    return letters;
}

// A data word a one-shot code does not take (G04 Q5): the control raises an alarm or ignores it.
class WordNotAllowed : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        bool restricted = false;
        const std::set<char> letters = allowed_letters(b, restricted);
        if (!restricted || b.g.size() != 1) return;   // several codes share the words: no verdict
        const auto tokens = b.view.tokens();
        for (std::uint32_t i = 0; i < tokens.size(); ++i) {
            const ast::Token& t = tokens[i];
            if (t.kind != ast::TokenKind::word || t.role() != ast::Role::parameter) continue;
            if (kFreeLetters.find(t.letter) != std::string_view::npos || letters.count(t.letter)) continue;
            const ast::Token& code = b.token(b.g.front().token);
            out.report(b.tree().range(t), fmt::format("{} does not take the word {}", b.tree().spelling(code), t.letter),
                       "remove the word or move it to a block of its own");
        }
    }
};

bool block_has_letter(const BlockContext& b, char letter) {
    for (const ast::Token& t : b.view.tokens())
        if (t.kind == ast::TokenKind::word && t.letter == letter) return true;
    return false;
}

// G02 without R or I/J/K; M98 without P (the table's `required` and `required_one_of`).
class RequiredWord : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        for_codes(b, [&](const ast::CodeRef& c) {
            if (!c.info) return;
            const ast::Token& t = b.token(c.token);
            for (const std::string& w : c.info->required)
                if (w.size() == 1 && !block_has_letter(b, w[0]))
                    out.report(b.tree().range(t), fmt::format("{} needs the word {}", b.tree().spelling(t), w),
                               fmt::format("add {} to the block", w));
            for (const auto& any : c.info->required_one_of) {
                bool found = false;
                std::string names;
                for (const std::string& w : any) {
                    found = found || (w.size() == 1 && block_has_letter(b, w[0]));
                    names += (names.empty() ? "" : ", ") + w;
                }
                if (!found && !any.empty())
                    out.report(b.tree().range(t), fmt::format("{} needs one of {}", b.tree().spelling(t), names),
                               fmt::format("add one of {} to the block", names));
            }
        });
    }
};

// G00 G01 in one block: two codes of one modal group; the control takes the last one.
class GroupConflict : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        for (std::size_t i = 0; i < b.g.size(); ++i)
            for (std::size_t j = 0; j < i; ++j) {
                const dialects::CodeInfo* x = b.g[i].info;
                const dialects::CodeInfo* y = b.g[j].info;
                if (!x || !y || x == y || x->group.empty() || x->group == "00" || x->group != y->group) continue;
                const ast::Token& t = b.token(b.g[i].token);
                out.report(b.tree().range(t),
                           fmt::format("{} and {} are both in modal group {}: only the last one acts",
                                       b.tree().spelling(b.token(b.g[j].token)), b.tree().spelling(t), x->group),
                           "keep one of them");
                break;
            }
    }
};

class TooManyM : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        const int limit = b.file.dialect.lexical.max_m_per_block;
        // FANUC takes up to three M codes per block with parameter 3404#7 M3B, which most current
        // machines set (the corpus' Doosan programs write two): only a machine file makes the
        // dialect's limit the machine's (issue 15).
        if (!b.file.setup.machine_given || limit <= 0 || static_cast<int>(b.m.size()) <= limit) return;
        const ast::Token& t = b.token(b.m[static_cast<std::size_t>(limit)].token);
        out.report(b.tree().range(t), fmt::format("{} M codes in one block; this control takes {}", b.m.size(), limit),
                   "split the M codes over several blocks");
    }
};

// G96 with the G50 S clamp in one block (semantics.md §4.1: "Must not be in the same block").
class CssWithClamp : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (!b.has_function(fn::css_on) || !b.has_function(fn::coordinate_system_setting)) return;
        out.report(b.view.range().size() ? trim(b) : b.view.range(),
                   "constant surface speed and the coordinate system setting (spindle clamp) in one block",
                   "program the S clamp in its own block before G96");
    }

private:
    static ast::Range trim(const BlockContext& b) {
        const auto tokens = b.view.tokens();
        return {tokens.front().begin, b.tree().end(tokens.back())};
    }
};

// G90 means a turning cycle in system A and absolute programming in B/C: worth a note when
// converting. Compares with every built-in dialect of the same kind of machine (opt-in).
class DiffersInOtherSystems : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        for (const ast::CodeRef& c : b.g) {
            if (!c.info) continue;
            std::string others;
            const dialects::Registry& all = dialects::builtin_registry();
            for (const std::string& id : all.ids()) {
                const dialects::Dialect* d = all.find(id);
                if (!d || d->id == b.file.dialect.id || d->machine != b.file.dialect.machine) continue;
                const dialects::CodeInfo* there = d->code(c.info->letter, c.info->key);
                if (there && there->function != c.info->function)
                    others += fmt::format("{}{}: {}", others.empty() ? "" : "; ", id, there->function);
            }
            if (others.empty()) continue;
            const ast::Token& t = b.token(c.token);
            out.report(b.tree().range(t), fmt::format("{} is {} here but means something else elsewhere ({})",
                                              b.tree().spelling(t), c.info->function, others),
                       "convert with kerf convert, which knows the tables");
        }
    }
};

}  // namespace

void add_dialect(Registry& r) {
    const auto rule = rule_maker(Category::dialect);
    // The dry run stops at the same block with alarm 010: one defect, this finding (not K4010's).
    r.add(explaining(static_rule<UnknownCode>(rule("K2001", "unknown-code", S::error,
        {"A G code the dialect does not have (M codes: K2010/K2011).", "The control stops with alarm 010 (improper G code).",
         "G384 X10.", "G84 X10.", "gcode-tables.md; dialects.md §1"})), {{alarms::improper_command, alarms::improper_command}}));
    // Detection found another control's program (analyzer/analyze.cpp reports it, nothing else).
    r.add(rule("K2009", "foreign-control", S::warning,
        {"A program of another control (Syntec, Fagor, a Macro Executor source, GRBL, a 3D printer, LinuxCNC): "
         "the evidence of a foreign control profile (dialects/data/foreign-*.toml) outweighs every dialect's.",
         "Read as FANUC, its statements would be dozens of false errors; on a FANUC control it would not run.",
         "%@MACRO\n#100:=0;", "(name the dialect if the file is FANUC-family: --dialect fanuc-mill)",
         "issue 15; dialects/SCHEMA.md Foreign controls"}));
    r.add(static_rule<UnlistedMCodeNote>(rule("K2010", "unlisted-m-code", S::info,
        {"The M codes the dialect's table does not list, one note per file (when the machine file lists no M codes).",
         "M codes beyond the standard ones belong to the machine builder: the control hands them to the machine, "
         "which may or may not have them. No alarm 010 (that is for G codes).",
         "M25 G49", "(m_codes = [\"M25\"] in the machine file)", "mcodes.md; issue 15"})));
    r.add(static_rule<MCodeNotOnMachine>(rule("K2011", "m-code-not-on-machine", S::warning,
        {"An M code that neither the dialect's table nor the machine file's m_codes list has.",
         "The machine has no such function: the block waits for an M-fin that never comes, or the PMC raises an alarm.",
         "M77", "M07", "machine/SCHEMA.md m_codes; issue 15"})));
    r.add(opt_in(static_rule<NotFitted>(rule("K2002", "code-not-fitted", S::warning,
        {"A code the dialect table marks as an option or as not fitted (opt-in: for machines without options).",
         "A machine without the option raises alarm 010 on the code.",
         "G12.1", "(use the machine that has polar interpolation)", "gcode-tables.md availability column"}))));
    r.add(static_rule<WordNotAllowed>(rule("K2003", "word-not-allowed", S::warning,
        {"A data word that the block's one-shot code does not take (G04 Q5).",
         "The control raises an alarm or ignores the word: the value you wrote has no effect.",
         "G04 Q5", "G04 P500", "gcode-tables.md words column"})));
    r.add(static_rule<RequiredWord>(rule("K2004", "required-word-missing", S::error,
        {"A code without a word it needs (G02 without R or I/J/K, G65 without P).",
         "The control raises an alarm, or moves in a straight line where an arc was meant.",
         "G02 X20. Z-5.", "G02 X20. Z-5. R5.", "gcode-tables.md required words; semantics.md §3"})));
    r.add(static_rule<GroupConflict>(rule("K2005", "modal-group-conflict", S::warning,
        {"Two codes of one modal group in a block (G00 G01).", "Only the last one acts; the other was probably a typo.",
         "G00 G01 X10. F0.2", "G01 X10. F0.2", "semantics.md §1.1"})));
    r.add(static_rule<TooManyM>(rule("K2006", "too-many-m-codes", S::error,
        {"More M codes in a block than the control takes (the dialect's max_m_per_block).",
         "The control raises an alarm or ignores the extra M codes.",
         "M03 M08", "M03\nM08", "dialects/SCHEMA.md max_m_per_block"})));
    r.add(static_rule<CssWithClamp>(rule("K2007", "css-and-clamp-in-one-block", S::error,
        {"G96 and the G50 S spindle clamp in the same block.",
         "The clamp must be set before CSS starts; in one block the spindle may run away to the machine limit.",
         "G50 G96 S200", "G50 S2000\nG96 S200", "semantics.md §4.1"})));
    r.add(opt_in(static_rule<DiffersInOtherSystems>(rule("K2008", "meaning-differs-between-dialects", S::info,
        {"A G code that means something else in another dialect of the same machine kind (G90 in lathe A vs B).",
         "A program moved to the other control without conversion does something else (opt-in, for conversions).",
         "G90 X20. Z-10. F0.2", "(kerf convert --from fanuc-lathe-a --to fanuc-lathe-b)", "dialects.md §4"}))));
}

}  // namespace kerf::analyzer::rules
