// Reference rules: labels, programs and loops a block points at must exist, once (dialects.md
// §3.6, §3.7; cycles.md; semantics.md §1.2).
#include <algorithm>
#include <climits>
#include <limits>
#include <span>
#include <unordered_set>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "analyzer/rules/common.hpp"
#include "ast/diagnostic_ids.hpp"
#include "dialects/alarms.hpp"
#include "references/references.hpp"

namespace kerf::analyzer::rules {

namespace {

using S = Severity;
namespace fn = dialects::functions;

struct Target {
    std::uint32_t token;
    std::int64_t label;
};

// Where a block jumps to in its own program (references/references.hpp): G70–G73 P/Q, GOTO n,
// M97 P, M98 Q without P. M99 P and M98 P Q name labels of other programs.
std::vector<Target> local_targets(const BlockContext& b) {
    std::vector<Target> out;
    for (const references::Reference& r : b.references()) {
        const bool local = r.kind == references::Kind::goto_label || r.kind == references::Kind::profile_label ||
                           r.kind == references::Kind::local_call_label ||
                           (r.kind == references::Kind::call_label && !r.label_program && !b.view.word('P'));
        if (local && r.value) out.push_back({r.token, *r.value});
    }
    return out;
}

// A block's words without its line break.
ast::Range block_range(const FileContext& file, std::uint32_t block) {
    const auto tokens = file.tree().block_tokens(block);
    if (tokens.empty()) return file.tree().block_range(block);
    return {tokens.front().begin, file.tree().end(tokens.back())};
}

// The labels of the block's program: built on the first jump that needs them (most CAM programs
// have none); FileContext shares them between the rules.
const LabelTable& labels(const BlockContext& b) { return b.file.labels(b.program); }

class LabelNotFound : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        for (const Target& t : local_targets(b))
            if (labels(b).count(t.label) == 0 && !out.drop_if_full(b.tree().range(b.token(t.token))))
                out.report(b.tree().range(b.token(t.token)), fmt::format("no block N{} in this program", t.label),
                           fmt::format("add N{} to the block meant, or correct the number", t.label));
    }
};

// Where the control searches a label from the top (FANUC, dialects.md §2), a jump to a repeated
// label lands on the first. Where it searches forward from the jump (Haas, `label_search =
// "forward"`), repeated labels are the local labels of macro sections (O09985 N4, N77, N78) and each
// jump has one target: nothing to report.
class AmbiguousLabel : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (b.file.dialect.lexical.label_search == dialects::LabelSearch::forward) return;
        for (const Target& t : local_targets(b))
            if (const int n = labels(b).count(t.label); n > 1) {
                if (out.drop_if_full(b.tree().range(b.token(t.token)))) continue;
                Finding& f = out.report(b.tree().range(b.token(t.token)),
                                        fmt::format("N{} is on {} blocks of this program: the control jumps to the first one", t.label, n),
                                        "give each target block a number of its own");
                if (!out.kept(f)) continue;   // past the rule's cap: the related blocks would go nowhere
                bool first = true;
                for (const std::uint32_t block : labels(b).blocks(t.label)) {
                    f.related.push_back({block_range(b.file, block), first ? fmt::format("N{}: the block the control jumps to", t.label)
                                                                          : fmt::format("N{} again", t.label)});
                    first = false;
                }
            }
    }
};

struct CalledProgram {
    std::int64_t number = 0;
    std::uint32_t token = 0;   // the P word
};

// The programs a block calls by a constant number (M98 P, G65 P, G66 P: references/references.hpp).
std::vector<CalledProgram> called_programs(const BlockContext& b) {
    std::vector<CalledProgram> out;
    for (const references::Reference& r : b.references())
        if (!references::is_label(r.kind) && r.value) out.push_back({*r.value, r.token});
    return out;
}

bool in_this_file(const BlockContext& b, std::int64_t number) {
    for (const ast::Program& p : b.file.typed.programs())
        if (p.number == number) return true;
    return false;
}

// M98 P / G65 P / G66 P: the program must exist (this file, or a file the program index reaches).
// One finding per missing program and file (issue 15: O09994 calls O9810 23 times); calls into the
// programs the machine keeps resident (.kerf.toml [programs] resident) are not findings.
class ProgramNotFound : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        for (const CalledProgram& call : called_programs(b)) {
            if (reported_.count(call.number) || b.file.program_exists(call.number)) continue;
            if (b.file.resident && b.file.resident(call.number)) continue;
            reported_.insert(call.number);
            out.report(b.tree().range(b.token(call.token)),
                       fmt::format("program O{:04} is not in this file, the files of its folder or the library folders ({})", call.number,
                                   b.file.dialect.alarms.name_of(alarms::program_not_found)),
                       fmt::format("put O{:04} into a file of its folder, name the folder that holds it in .kerf.toml "
                                   "[programs] library, or, if the machine keeps it in memory (a probe macro), list it in "
                                   "[programs] resident", call.number));
        }
    }
    void state(StateKey& key) const override {
        for (const std::int64_t n : reported_) key.add(n);
    }

private:
    std::set<std::int64_t> reported_;   // the numbers reported in this file (one finding each)
};

// A call whose program is in several other files (project/index.hpp): which one runs depends on
// which was loaded into the control; kerf takes the nearest (same folder, nearest folder, path order).
class ProgramInSeveralFiles : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (!b.file.program_files) return;
        for (const CalledProgram& call : called_programs(b)) {
            if (in_this_file(b, call.number)) continue;
            const std::vector<std::string> files = b.file.program_files(call.number);
            if (files.size() < 2) continue;
            std::string others;
            for (std::size_t i = 1; i < files.size(); ++i) others += (i > 1 ? ", " : "") + files[i];
            out.report(b.tree().range(b.token(call.token)),
                       fmt::format("program O{:04} is in {} files: the dry run takes {}, also in {}", call.number, files.size(),
                                   files.front(), others),
                       "keep one copy of the program, or give the copies their own numbers");
        }
    }
};

// DO m / END m pairs and their depth (dialects.md §3.7; alarms 124 and 126).
class Loops : public StaticCheck {
public:
    explicit Loops(bool depth) : depth_(depth) {}
    void begin_program(const FileContext&, std::size_t, Reporter&) override { open_.clear(); }
    void block(const BlockContext& b, Reporter& out) override {
        for (const std::uint32_t s : b.statements()) {
            const ast::Statement& st = b.tree().statements[static_cast<std::size_t>(b.token(s).payload)];
            const bool opens = st.kind == ast::StatementKind::while_do || st.kind == ast::StatementKind::do_;
            if (!opens && st.kind != ast::StatementKind::end) continue;
            const auto m = constant_of(b.tree(), st.label);
            const auto number = m ? ast::truncated_integer(*m) : std::nullopt;
            // DO 99999999999: no loop number at all (the dry run raises alarm 126 on it).
            if (!number || *number < INT_MIN || *number > INT_MAX) continue;
            const int label = static_cast<int>(*number);
            if (opens) open(b, s, label, out);
            else close(b, s, label, out);
        }
    }
    void state(StateKey& key) const override {
        key.add(depth_);
        for (const auto& [token, label] : open_) {
            key.token(token);
            key.add(label);
        }
    }
    void end_program(const FileContext& file, std::size_t, Reporter& out) override {
        if (depth_) return;
        for (const auto& [token, label] : open_)
            out.report(file.tree().range(file.tree().tokens[token]), fmt::format("DO {} has no END {} ({})", label, label, file.dialect.alarms.name_of(alarms::loop_nesting)),
                       fmt::format("close the loop with END {}", label));
    }

private:
    void open(const BlockContext& b, std::uint32_t s, int label, Reporter& out) {
        if (!depth_ && (label < 1 || label > 3))
            out.report(b.tree().range(b.token(s)), fmt::format("DO {}: the loop number must be 1, 2 or 3 ({})", label, b.file.dialect.alarms.name_of(alarms::loop_number)),
                       "number loops 1 to 3");
        open_.push_back({s, label});
        if (depth_ && open_.size() == 4)
            out.report(b.tree().range(b.token(s)), fmt::format("WHILE/DO nested deeper than 3 ({})", b.file.dialect.alarms.name_of(alarms::loop_nesting)),
                       "move the inner loop into a macro (G65) or a subprogram");
    }
    void close(const BlockContext& b, std::uint32_t s, int label, Reporter& out) {
        for (std::size_t i = open_.size(); i-- > 0;)
            if (open_[i].second == label) {
                if (!depth_ && i + 1 != open_.size())
                    out.report(b.tree().range(b.token(s)), fmt::format("END {} closes DO {} before the inner loops end", label, label),
                               "close the inner loops first");
                open_.resize(i);
                return;
            }
        if (!depth_)
            out.report(b.tree().range(b.token(s)), fmt::format("END {} without its DO ({})", label, b.file.dialect.alarms.name_of(alarms::loop_nesting)),
                       fmt::format("add WHILE [...] DO {} before it, or remove it", label));
    }
    bool depth_;
    std::vector<std::pair<std::uint32_t, int>> open_;
};

struct LoopsDepth : Loops {
    LoopsDepth() : Loops(true) {}
};
struct LoopsPairs : Loops {
    LoopsPairs() : Loops(false) {}
};

bool ends_program(const BlockContext& b) {
    return b.has_function(fn::program_end) || b.has_function(fn::program_end_rewind) ||
           b.has_function(fn::subprogram_return);
}

class MissingEnd : public StaticCheck {
public:
    void begin_program(const FileContext&, std::size_t, Reporter&) override {
        ended_ = false;
        code_ = false;
    }
    void block(const BlockContext& b, Reporter&) override {
        ended_ = ended_ || ends_program(b);
        code_ = code_ || b.view.block().kind == ast::BlockKind::code;
    }
    void state(StateKey& key) const override { key.add(ended_ * 2 + code_); }
    void end_program(const FileContext& file, std::size_t program, Reporter& out) override {
        const auto& programs = file.typed.programs();
        const ast::Program& p = programs[program];
        if (ended_ || !code_ || (!p.number && program + 1 < programs.size())) return;   // a header before O
        if (fragment(file, p)) return;
        const ast::Range at = p.o_token >= 0 ? file.tree().range(file.tree().tokens[static_cast<std::size_t>(p.o_token)])
                                             : trimmed_block(file, p.first_block);
        out.report(at, p.number ? fmt::format("program O{:04} has no M30, M02 or M99", *p.number)
                                : std::string("the program has no M30, M02 or M99"),
                   "end a main program with M30 (or M02), a subprogram with M99");
    }

private:
    // A listing fragment is not a program, so it needs no end (reference/README.md "Example files":
    // the seeds print excerpts). It is one when blocks are marked as left out (a "..." line, S0113,
    // reported by K1013), or when nothing makes it a program: no O number and no '%' in the file
    // (dialects.md §3.4 starts a program with its O number; tape files with '%').
    static bool fragment(const FileContext& file, const ast::Program& p) {
        const ast::SyntaxTree& tree = file.tree();
        const std::uint32_t begin = tree.blocks[p.first_block].begin;
        const std::uint32_t end = p.end_block < tree.block_count() ? tree.blocks[p.end_block].begin
                                                                    : static_cast<std::uint32_t>(tree.text.size());
        for (const ast::Diagnostic& d : tree.diagnostics)
            if (d.code == ast::diagnostic_id::listing_ellipsis && d.range.begin >= begin && d.range.begin < end) return true;
        if (p.number) return false;
        return std::none_of(tree.blocks.begin(), tree.blocks.end(),
                            [](const ast::Block& b) { return b.kind == ast::BlockKind::percent; });
    }
    static ast::Range trimmed_block(const FileContext& file, std::uint32_t b) {
        ast::Range r = file.tree().block_range(b);
        while (r.end > r.begin && std::string_view(" \t\r\n").find(file.tree().text[r.end - 1]) != std::string_view::npos) --r.end;
        return r;
    }
    bool ended_ = false, code_ = false;
};

// Blocks after M30/M02 or an unconditional GOTO that nothing jumps to (the control never runs them).
class Unreachable : public StaticCheck {
public:
    void begin_program(const FileContext& file, std::size_t, Reporter&) override {
        // The same for every program of the file; shared by the copies of incremental checking
        // (an edit that changes a target is checked whole: static_facts digests them).
        if (!targets_) targets_ = file.shared_jump_targets();
        dead_ = false;
        reported_ = false;
    }
    void state(StateKey& key) const override { key.add((targets_ && targets_->computed) * 4 + dead_ * 2 + reported_); }
    void block(const BlockContext& b, Reporter& out) override {
        if (targets_->computed) return;   // GOTO #1 may reach any label
        const auto n = b.view.sequence_label();
        if (n && targets_->has(*n)) dead_ = false;
        if (dead_ && !reported_ && b.view.block().kind == ast::BlockKind::code && !b.view.block().has(ast::block_flags::deleted) &&
            !heading(b)) {
            out.report(block_text_range(b), "no path reaches this block: it follows the end of the program or a GOTO",
                       "remove the dead blocks, or give them a label that a GOTO or M98 Q jumps to");
            reported_ = true;
        }
        if (b.has_function(fn::program_end) || b.has_function(fn::program_end_rewind) || unconditional_goto(b)) dead_ = true;
    }

private:
    // "N900 ( ALARMS )" between a GOTO and the labels below it (Renishaw O09994): a heading that
    // does nothing when it is not run, not dead code worth a finding.
    static bool heading(const BlockContext& b) {
        const auto tokens = b.view.tokens();
        return std::all_of(tokens.begin(), tokens.end(), [](const ast::Token& t) {
            return t.kind == ast::TokenKind::comment || t.kind == ast::TokenKind::eob || (t.kind == ast::TokenKind::word && t.letter == 'N');
        });
    }
    static bool unconditional_goto(const BlockContext& b) {
        if (b.view.block().has(ast::block_flags::deleted)) return false;
        for (const std::uint32_t s : b.statements())
            if (b.tree().statements[static_cast<std::size_t>(b.token(s).payload)].kind == ast::StatementKind::goto_) return true;
        return false;
    }
    std::shared_ptr<const JumpTargets> targets_;
    bool dead_ = false, reported_ = false;
};

// The same N on several blocks of one program (the MANIFEST's student programs: O0001 N130–N150,
// O0005 N30/N70): searching for the block, restarting the program at it or renumbering it finds
// the first one. Labels that jumps land on are K3002's; in a dialect whose label search goes forward
// from the jump (Haas), repeated labels are local labels on purpose and not reported (issue 15).
class DuplicateSequenceNumber : public ProgramCheck {
public:
    // One finding per program, at the first block that repeats a number: it names every repeated
    // number of the program with its blocks. Computed from the label table, not by a walk: a CAM
    // program whose N numbers wrap repeats on nearly every block, and the language server checks it
    // again after every edit that touches a label (incremental.hpp).
    void program(const FileContext& file, std::size_t program, Reporter& out) const override {
        // Where labels are searched forward from the jump (Haas), N numbers are local labels: the
        // Renishaw macros repeat N76 (INCH) / N77 (METRIC) in each section on purpose (issue 15).
        if (file.dialect.lexical.label_search == dialects::LabelSearch::forward) return;
        const LabelTable& labels = file.labels(program);
        const JumpTargets& targets = file.jump_targets();
        struct Repeat {
            std::uint32_t first;   // the first block whose N is exactly the number
            std::int64_t number;
        };
        std::vector<Repeat> repeats;
        std::uint32_t at = std::numeric_limits<std::uint32_t>::max();   // the first block that repeats one
        const std::span<const LabelTable::Entry> entries = labels.entries();
        for (std::size_t lo = 0, hi = 0; lo < entries.size(); lo = hi) {
            const std::int64_t n = entries[lo].number();
            while (hi < entries.size() && entries[hi].number() == n) ++hi;
            // A number on one block, or one a jump lands on (K3002's), is no finding. N10.5 counts
            // as a block of label 10 but is not N10 itself.
            if (hi - lo < 2 || targets.has(n)) continue;
            std::optional<std::uint32_t> first, second;
            for (std::size_t i = lo; i < hi && !second; ++i) {
                if (entries[i].value != static_cast<double>(n)) continue;
                (first ? second : first) = entries[i].block;
            }
            if (!first) continue;
            repeats.push_back({*first, n});
            if (second) at = std::min(at, *second);
        }
        if (at == std::numeric_limits<std::uint32_t>::max()) return;
        // The message and the related locations name the first kListed numbers (in the order they
        // first appear) and count the others.
        constexpr std::size_t kListed = 10;
        const std::size_t listed = std::min(repeats.size(), kListed);
        std::partial_sort(repeats.begin(), repeats.begin() + static_cast<std::ptrdiff_t>(listed), repeats.end(),
                          [](const Repeat& a, const Repeat& b) { return a.first < b.first; });
        std::string list;
        for (std::size_t k = 0; k < listed; ++k) list += fmt::format("{}N{}", list.empty() ? "" : ", ", repeats[k].number);
        if (repeats.size() > kListed) list += fmt::format(" and {} more numbers", repeats.size() - kListed);
        Finding& f = out.report(block_range(file, at),
                                fmt::format("{} {} on several blocks of this program: a search or a restart finds the first",
                                            list, repeats.size() == 1 ? "is" : "are"),
                                "give each block a number of its own (kerf fmt --block-numbers renumber)");
        for (std::size_t k = 0; k < listed; ++k) {
            const std::int64_t m = repeats[k].number;
            const std::vector<std::uint32_t> blocks = labels.blocks(m);
            for (std::size_t j = 0; j < blocks.size(); ++j)
                f.related.push_back({block_range(file, blocks[j]), j == 0 ? fmt::format("N{}: the first", m) : fmt::format("N{} again", m)});
        }
    }
};

class ProgramNumbers : public StaticCheck {
public:
    void begin_program(const FileContext& file, std::size_t program, Reporter& out) override {
        const ast::Program& p = file.typed.programs()[program];
        if (!p.number || p.o_token < 0) return;
        const ast::Range at = file.tree().range(file.tree().tokens[static_cast<std::size_t>(p.o_token)]);
        for (std::size_t i = 0; i < program; ++i)
            if (file.typed.programs()[i].number == p.number) {
                Finding& f = out.report(at, fmt::format("program O{:04} is defined twice in this file: calls reach the first one", *p.number),
                                        "renumber one of them");
                const std::int32_t first = file.typed.programs()[i].o_token;
                if (first >= 0) f.related.push_back({file.tree().range(file.tree().tokens[static_cast<std::size_t>(first)]), fmt::format("the first O{:04}", *p.number)});
                return;
            }
    }
    void block(const BlockContext&, Reporter&) override {}
};

class ProtectedNumber : public StaticCheck {
public:
    void begin_program(const FileContext& file, std::size_t program, Reporter& out) override {
        const ast::Program& p = file.typed.programs()[program];
        if (!p.number || p.o_token < 0 || *p.number < 8000 || *p.number > 9999) return;
        out.report(file.tree().range(file.tree().tokens[static_cast<std::size_t>(p.o_token)]),
                   fmt::format("O{:04} is in the range {} that the control can protect from editing and loading",
                               *p.number, *p.number < 9000 ? "O8000-O8999" : "O9000-O9999"),
                   "use a number below O8000 unless this is a protected macro on purpose");
    }
    void block(const BlockContext&, Reporter&) override {}
};

}  // namespace

}  // namespace kerf::analyzer::rules

namespace kerf::analyzer {

std::vector<std::int64_t> jump_targets(const ast::SyntaxTree& tree, bool& computed) {
    using rules::constant_of;
    std::vector<std::int64_t> out;
    computed = false;
    for (const ast::Statement& st : tree.statements) {
        if (st.label < 0) continue;
        if (const auto v = constant_of(tree, st.label)) {
            if (const auto label = ast::truncated_integer(*v)) out.push_back(*label);
        } else if (st.kind == ast::StatementKind::goto_ || st.kind == ast::StatementKind::if_goto) computed = true;
    }
    for (const ast::Token& tok : tree.tokens)   // P/Q of calls and cycles: any number
        if (tok.kind == ast::TokenKind::word && (tok.letter == 'P' || tok.letter == 'Q') && tok.is_number())
            if (const auto label = ast::truncated_integer(tree.number_value(tok))) out.push_back(*label);
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace kerf::analyzer

namespace kerf::analyzer::rules {

void add_references(Registry& r) {
    const auto rule = rule_maker(Category::references);
    r.add(with_alarms(static_rule<LabelNotFound>(rule("K3001", "label-not-found", S::error,
        {"G70–G73 P/Q, GOTO n or M98 Q n to a sequence number the program does not have.",
         "The control stops with alarm 060 (cycles), 128 (GOTO) or 078 (M98 Q) in the middle of the job.",
         "G71 P100 Q200 U0.5 W0.1 F0.3\nN100 G00 X20.\nN210 G01 Z-10.", "G71 P100 Q200 U0.5 W0.1 F0.3\nN100 G00 X20.\nN200 G01 Z-10.",
         "cycles.md §5; dialects.md §3.6, §3.7"})), {{alarms::profile_sequence, alarms::profile_sequence}, {alarms::goto_target, alarms::goto_target}}));
    r.add(static_rule<AmbiguousLabel>(rule("K3002", "ambiguous-label", S::warning,
        {"A jump (P/Q, GOTO, M98 Q) to a sequence number that several blocks carry.",
         "The control searches from the top and takes the first block: maybe not the one you meant.",
         "GOTO 10\nN10 X1.\nN10 X2.", "GOTO 10\nN10 X1.\nN20 X2.", "dialects.md §2 Sequence number"})));
    // One missing program is one finding: K3003 at the call hides the dry run's alarm 078 (K4009) there.
    r.add(explaining(static_rule<ProgramNotFound>(rule("K3003", "program-not-found", S::error,
        {"M98 P, G65 P or G66 P to a program that is in no file kerf can reach: this file, the files of its "
         "folder (by the O numbers inside them) and the .kerf.toml's [programs] library folders; once per program "
         "and file, and not for the [programs] resident ranges.",
         "The control stops with alarm 078 when the call is reached.", "M98 P1234", "M98 P1000 (O1000 in a file of the folder)",
         "dialects.md §3.6"})), {{alarms::program_not_found, alarms::program_not_found}}));
    r.add(with_alarms(static_rule<LoopsPairs>(rule("K3004", "loop-mismatch", S::error,
        {"DO m without END m, END m without DO m, loops crossing, or a loop number other than 1–3.",
         "The control stops with alarm 124 or 126.", "WHILE [#1 LT 3] DO 1\n#1=#1+1\nEND 2",
         "WHILE [#1 LT 3] DO 1\n#1=#1+1\nEND 1", "dialects.md §3.7"})), {{alarms::loop_nesting, alarms::loop_nesting}, {alarms::loop_number, alarms::loop_number}}));
    r.add(static_rule<LoopsDepth>(rule("K3005", "loop-nesting-too-deep", S::error,
        {"WHILE/DO loops nested more than 3 deep.", "The control stops with alarm 124.",
         "DO1 DO2 DO3 DO1 (four levels)", "three levels, the fourth in a G65 macro", "dialects.md §3.7"})));
    r.add(static_rule<MissingEnd>(rule("K3006", "missing-program-end", S::warning,
        {"A program without M30, M02 or M99 (a listing fragment is not a program: one with '...' for left-out blocks, or without O number and '%').",
         "The control runs off the end of the memory of the program: no rewind, no reset of modal state.",
         "O0001\nG00 X0.", "O0001\nG00 X0.\nM30", "dialects.md §3.4"})));
    r.add(static_rule<Unreachable>(rule("K3007", "unreachable-block", S::warning,
        {"Blocks after M30/M02 or an unconditional GOTO that nothing jumps to.",
         "They never run: a forgotten operation, or a label that was renumbered.",
         "M30\nG00 X100.", "G00 X100.\nM30", "dialects.md §3.4, §3.7"})));
    r.add(static_rule<ProgramNumbers>(rule("K3008", "duplicate-program-number", S::error,
        {"The same O number twice in one file.", "Calls reach only the first; loading the file may overwrite a program.",
         "O0100\nM30\nO0100\nM99", "O0100\nM30\nO0101\nM99", "corpus O0100"})));
    r.add(static_rule<ProtectedNumber>(rule("K3009", "protected-program-number", S::info,
        {"An O number in O8000–O9999, the ranges FANUC parameter 3202 can protect.",
         "A protected program cannot be edited or loaded over; macro makers use these numbers on purpose.",
         "O9001", "O1001", "[FANUC] parameter 3202 NE8/NE9"})));
    r.add(program_rule<DuplicateSequenceNumber>(rule("K3011", "duplicate-sequence-number", S::warning,
        {"The same sequence number on several blocks of one program (not a jump target: that is K3002).",
         "A search for the block, a restart at it or a renumbering finds the first: the operator restarts at the wrong place.",
         "N130 M06 T02\nN140 G43 H02\nN130 G00 X0 Y0", "N130 M06 T02\nN140 G43 H02\nN250 G00 X0 Y0",
         "corpus MANIFEST 'duplicate N numbers' (O0001, O0005); dialects.md §2 Sequence number"})));
    r.add(static_rule<ProgramInSeveralFiles>(rule("K3010", "program-in-several-files", S::warning,
        {"M98 P, G65 P or G66 P to a program number that several other files of the folder (or the library "
         "folders) hold.",
         "The control runs whichever copy was loaded into its memory; the dry run takes the nearest file "
         "(same folder, then the nearest folder, then path order) and may check another program than the machine runs.",
         "M98 P1000 (O1000 in a.nc and in old/a.nc)", "M98 P1000 (O1000 in one file)", "dialects.md §3.6"})));
}

}  // namespace kerf::analyzer::rules
