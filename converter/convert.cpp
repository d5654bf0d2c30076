// The converter's pass over the bound tree (converter/convert.hpp). One block at a time, in text
// order, with the modal state the conversion needs (G90/G91 in both dialects, the modal motion code,
// the return level, the feed mode and plane for --expand); a few facts are gathered first (the
// profile blocks of G70–G73, which G99 system A can do without, the dry run for G52 and --expand).
// Each block's edits are collected, sorted and appended, so the edit list stays in text order.
#include "converter/convert.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

#include "converter/codes.hpp"
#include "converter/dry_run.hpp"
#include "converter/expand.hpp"
#include "converter/numbers.hpp"
#include "converter/words.hpp"
#include "dialects/functions.hpp"
#include "interpreter/default_setup.hpp"

namespace kerf::converter {

namespace fn = dialects::functions;
using ast::Role;
using ast::Token;
using ast::TokenKind;
using dialects::CodeInfo;
using dialects::FunctionId;

const char* to_string(ReportKind kind) {
    switch (kind) {
    case ReportKind::unconverted: return "not converted";
    case ReportKind::syntax_error: return "syntax error";
    case ReportKind::expanded: return "expanded";
    case ReportKind::note: return "note";
    }
    return "?";
}

bool Conversion::clean() const {
    return std::none_of(reports.begin(), reports.end(), [](const Report& r) {
        return r.kind == ReportKind::unconverted || r.kind == ReportKind::syntax_error;
    });
}

void Edits::replace(ast::Range range, std::string_view text) {
    edits_.push_back({range.begin, range.end, static_cast<std::uint32_t>(buffer_.size()), static_cast<std::uint32_t>(text.size())});
    buffer_.append(text);
    growth_ += static_cast<std::int64_t>(text.size()) - static_cast<std::int64_t>(range.size());
}

Edit Edits::operator[](std::size_t i) const {
    const Raw& r = edits_[i];
    return {{r.begin, r.end}, std::string_view(buffer_).substr(r.text, r.length)};
}

std::string apply(std::string_view text, const Edits& edits) {
    std::string out;
    out.reserve(static_cast<std::size_t>(static_cast<std::int64_t>(text.size()) + std::max<std::int64_t>(edits.growth(), 0)));
    std::uint32_t at = 0;
    for (std::size_t i = 0; i < edits.size(); ++i) {
        const Edit e = edits[i];
        out.append(text.substr(at, e.range.begin - at));
        out.append(e.text);
        at = e.range.end;
    }
    out.append(text.substr(at));
    return out;
}

Reading reading_of(const dialects::Dialect& d) {
    Reading r;
    r.calculator_decimal = d.lexical.calculator_decimal;
    r.dwell_p_seconds = d.lexical.dwell_p_seconds;
    // machine/machine.cpp resolve_for_dialect: the G52 reading from the function ids.
    if (!d.codes_with_function(fn::local_system_current_point).empty())
        r.g52 = d.codes_with_function(fn::local_system_cancel).empty() ? LocalSystem::current_point : LocalSystem::current_point_g152;
    r.g54_cancels_g52 = r.g52 == LocalSystem::current_point_g152;
    r.diameter_x = d.machine == dialects::MachineKind::lathe && d.lexical.is_diameter('X');
    return r;
}

Reading reading_of(const dialects::Dialect&, const interpreter::Setup& s) {
    Reading r;
    r.calculator_decimal = s.calculator_decimal;
    r.increment_digits = s.increment_mm < 0.0005 ? 4 : 3;
    r.dwell_p_seconds = s.dwell_p_in_seconds;
    r.g52 = !s.g52_current_point ? LocalSystem::vector_shift
                                 : (s.g52_zeros_cancel ? LocalSystem::current_point : LocalSystem::current_point_g152);
    r.g54_cancels_g52 = s.g54_cancels_g52;
    r.diameter_x = s.diameter_x;
    return r;
}

namespace {

// One edit of the block being converted; sorted by place (insertions first) before it is kept.
struct Pending {
    std::uint32_t begin = 0, end = 0;
    std::uint32_t order = 0;
    std::string text;
};

bool is_axis_role(Role r) { return r == Role::axis_absolute || r == Role::axis_incremental; }

enum BlockFlag : std::uint8_t { kProfile = 1, kConstruct = 2 };

class Converter {
public:
    Converter(const ast::TypedFile& file, const dialects::Dialect& to, const Options& options)
        : file_(file), tree_(file.tree()), from_(file.dialect()), to_(to), options_(options),
          rf_(options.from.value_or(reading_of(from_))), rt_(options.to.value_or(reading_of(to))), codes_(from_, to) {
        src_modes_ = !from_.codes_with_function(fn::incremental_programming).empty();
        tgt_abs_code_ = codes_.target_code(fn::absolute_programming);
        tgt_inc_code_ = codes_.target_code(fn::incremental_programming);
        can_cycle_ = has_canned_cycles(to_);
        power_on_differences();
        tgt_modes_ = !to_.codes_with_function(fn::incremental_programming).empty();
        src_power_incremental_ = power_on(from_, fn::incremental_programming);
        tgt_power_incremental_ = power_on(to_, fn::incremental_programming);
        lengths_differ_ = rf_.calculator_decimal != rt_.calculator_decimal || rf_.increment_digits != rt_.increment_digits;
        line_ending_ = detect_line_ending(tree_.text);
    }

    Conversion run() {
        // A lathe program says nothing a mill dialect can say by meaning (axes, diameters, cycles).
        if (from_.machine != to_.machine) {
            const char* kinds[] = {"lathe", "mill"};
            report({0, 0}, ReportKind::unconverted, from_.id,
                   fmt::format("a {} program: {} is a dialect for {}s; nothing was converted", kinds[static_cast<int>(from_.machine)],
                               to_.id, kinds[static_cast<int>(to_.machine)]));
            return std::move(out_);
        }
        prepare();
        for (std::size_t b = 0; b < tree_.block_count(); ++b) convert_block(b);
        report_syntax_errors();
        std::stable_sort(out_.reports.begin(), out_.reports.end(),
                         [](const Report& a, const Report& b) { return a.range.begin < b.range.begin; });
        return std::move(out_);
    }

private:
    const ast::TypedFile& file_;
    const ast::SyntaxTree& tree_;
    const dialects::Dialect& from_;
    const dialects::Dialect& to_;
    Options options_;
    Reading rf_, rt_;
    CodeMap codes_;
    Conversion out_;
    std::string line_ending_;
    bool src_modes_ = false, tgt_modes_ = false;
    const CodeInfo* tgt_abs_code_ = nullptr;
    const CodeInfo* tgt_inc_code_ = nullptr;
    bool can_cycle_ = false;
    // Power-on modes the target lacks (dialects.md §3.8 and the tables' `default`): the source's
    // mode of each family where the two differ, written into each program's first code block.
    std::vector<const CodeInfo*> power_on_codes_;
    std::vector<std::string> power_on_missing_;
    bool source_moves_at_power_on_ = false;   // the source has a power-on motion mode (G00)
    bool target_moves_at_power_on_ = false;
    bool power_on_pending_ = false;
    bool in_first_program_ = true;
    const CodeInfo* power_on_motion_ = nullptr;   // the source's power-on G00 where the target has none
    bool src_power_incremental_ = false, tgt_power_incremental_ = false;
    bool lengths_differ_ = false;

    // Facts gathered before the pass.
    std::vector<std::uint8_t> flags_;                    // per block: BlockFlag
    std::unordered_map<std::uint32_t, std::string> return_level_;   // G99 token → why it cannot go ("" = it can)
    std::optional<SourceRun> run_;
    std::set<std::uint32_t> expandable_;                 // construct blocks --expand replaces
    bool header_done_ = false;

    // Text-order state, reset at each program start.
    bool src_incremental_ = false;
    bool tgt_incremental_ = false;
    const CodeInfo* motion_ = nullptr;                  // the source's modal group-01 code
    std::uint32_t motion_at_ = 0;   // where the modal group-01 code is written (its line when reported)
    bool feed_per_rev_ = false;
    dialects::PlaneTrait plane_ = dialects::PlaneTrait::xy;
    bool compensating_ = false;
    bool transformed_ = false;

    // Per-block scratch, reused.
    struct Rewrite {
        std::uint32_t token = 0;
        char letter = 0;               // the address letter it gets (0: as written)
        std::optional<std::string> value;
        bool value_fixed = false;      // a computed value (G52): readings leave it alone
    };
    std::vector<Rewrite> rewrites_;
    std::vector<ast::CodeRef> g_, m_;
    std::vector<const CodeInfo*> infos_;
    std::vector<Pending> pending_;
    std::uint32_t order_ = 0;

    // --- helpers ------------------------------------------------------------------------------

    static bool power_on(const dialects::Dialect& d, FunctionId f) {
        for (const CodeInfo* c : d.codes_with_function(f))
            if (c->power_on_default) return true;
        return false;
    }

    static std::string detect_line_ending(std::string_view text) {
        const std::size_t n = text.find_first_of("\r\n");
        if (n == std::string_view::npos) return "\n";
        if (text[n] == '\r') return n + 1 < text.size() && text[n + 1] == '\n' ? "\r\n" : "\r";
        return "\n";
    }

    // 1-based line of an offset, for report texts: counted on from the last one asked (the pass
    // asks in text order), so a file with many reports costs one walk over its text.
    mutable std::uint32_t line_at_ = 0, line_ = 1;
    std::uint32_t line_of(std::uint32_t offset) const {
        if (offset < line_at_) line_at_ = 0, line_ = 1;
        line_ += static_cast<std::uint32_t>(std::count(tree_.text.begin() + line_at_, tree_.text.begin() + offset, '\n'));
        line_at_ = offset;
        return line_;
    }

    std::string_view spelling(const Token& t) const { return tree_.spelling(t); }

    // A block's text for a report: without its line break.
    std::string block_text(const ast::BlockView& view) const {
        std::string_view s = tree_.slice(view.range());
        while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
        return std::string(s);
    }

    void edit(std::uint32_t begin, std::uint32_t end, std::string text) {
        pending_.push_back({begin, end, order_++, std::move(text)});
    }
    void replace_token(const Token& t, std::string text) { edit(t.begin, t.begin + t.length, std::move(text)); }

    // Removes a token with the blanks after it (before it when it is the last on its line), so that
    // inserting "G91 " and removing it again give back the same bytes.
    void remove_token(std::uint32_t index) {
        const Token& t = tree_.tokens[index];
        std::uint32_t begin = t.begin, end = t.begin + t.length;
        const std::string_view text = tree_.text;
        std::uint32_t after = end;
        while (after < text.size() && (text[after] == ' ' || text[after] == '\t')) ++after;
        const bool last = after >= text.size() || text[after] == '\n' || text[after] == '\r' || text[after] == ';';
        if (!last) end = after;
        else
            while (begin > 0 && (text[begin - 1] == ' ' || text[begin - 1] == '\t')) --begin;
        // Not back into a removal before it ("G52 X0 Y0" losing both words).
        for (const Pending& p : pending_)
            if (p.end > begin && p.end <= t.begin) begin = p.end;
        edit(begin, end, {});
    }

    void report(ast::Range range, ReportKind kind, std::string construct, std::string reason) {
        out_.reports.push_back({range, kind, std::move(construct), std::move(reason)});
    }
    void report_token(const Token& t, ReportKind kind, std::string reason) {
        report(t.range(), kind, std::string(spelling(t)), std::move(reason));
    }

    // "in fanuc-lathe-a, G99 is Feed per revolution": the danger of leaving a code as it is.
    std::string hazard(char letter, std::optional<dialects::CodeKey> key) const {
        if (!key) return {};
        const CodeInfo* there = to_.code(letter, *key);
        if (!there) return {};
        return fmt::format(" (in {}, {} is {}: the output reads it so until you edit it)", to_.id, there->spelling, there->en);
    }

    Rewrite& rewrite(std::uint32_t token) {
        for (Rewrite& r : rewrites_)
            if (r.token == token) return r;
        Rewrite r;
        r.token = token;
        rewrites_.push_back(std::move(r));
        return rewrites_.back();
    }

    // The address letter and the value of a word, each as the rewrite says or as written.
    void flush_rewrites() {
        for (const Rewrite& r : rewrites_) {
            const Token& t = tree_.tokens[r.token];
            const char letter = r.letter && t.has(ast::token_flags::lower_case) ? static_cast<char>(std::tolower(r.letter)) : r.letter;
            if (!r.value) {
                if (letter && letter != spelling(t).front()) edit(t.begin, t.begin + 1, std::string(1, letter));
                continue;
            }
            std::string head = letter_part(t);
            if (letter) head[0] = letter;
            replace_token(t, head + *r.value);
        }
        rewrites_.clear();
    }

    std::string letter_part(const Token& t) const {
        const std::string_view s = spelling(t);
        return std::string(s.substr(0, s.size() - tree_.value_spelling(t).size()));
    }

    void flush_block() {
        flush_rewrites();
        std::sort(pending_.begin(), pending_.end(), [](const Pending& a, const Pending& b) {
            if (a.begin != b.begin) return a.begin < b.begin;
            const bool ai = a.begin == a.end, bi = b.begin == b.end;
            if (ai != bi) return ai;   // an insertion before a replacement at the same place
            return a.order < b.order;
        });
        std::uint32_t at = 0;
        for (const Pending& p : pending_) {
            if (p.begin < at) continue;   // overlapping: the first edit of a place wins
            out_.edits.replace({p.begin, p.end}, p.text);
            at = p.end;
        }
        pending_.clear();
    }

    // --- facts before the pass ----------------------------------------------------------------

    void prepare() {
        flags_.assign(tree_.block_count(), 0);
        for (const ast::Program& p : file_.programs()) {
            mark_profiles(p);
            if (needs_return_level_pass()) scan_return_levels(p);
        }
        prepare_run();
    }

    // G70–G73 P..Q (cycles.md §1–§4): the cycle reads its profile blocks with the G90/G91 of the
    // cycle block (interpreter/executor_cycles.cpp cycle_profile), so their U/W stay U/W.
    void mark_profiles(const ast::Program& p) {
        std::unordered_map<std::int64_t, std::uint32_t> labels;
        bool indexed = false;
        for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
            if (tree_.blocks[b].kind != ast::BlockKind::code) continue;
            const ast::BlockView view = file_.block(b);
            view.collect_codes(g_, m_);
            bool profile_cycle = false;
            for (const ast::CodeRef& c : g_)
                if (c.info && c.info->has(dialects::traits::profile_cycle)) profile_cycle = true;
            if (!profile_cycle) continue;
            const auto pw = view.word('P'), qw = view.word('Q');
            if (!pw || !qw) continue;
            const auto pv = ast::integer_value(tree_, tree_.tokens[*pw]), qv = ast::integer_value(tree_, tree_.tokens[*qw]);
            if (!pv || !qv) continue;
            if (!indexed) {
                for (std::uint32_t k = p.first_block; k < p.end_block; ++k)
                    if (const auto n = file_.block(k).sequence_number())
                        labels.emplace(static_cast<std::int64_t>(std::llround(*n)), k);
                indexed = true;
            }
            const auto first = labels.find(*pv), last = labels.find(*qv);
            if (first == labels.end() || last == labels.end() || last->second < first->second) continue;
            for (std::uint32_t k = first->second; k <= last->second; ++k) flags_[k] |= kProfile;
        }
    }

    bool needs_return_level_pass() const {
        for (const CodeInfo& c : from_.codes())
            if (codes_(c).action == CodeAction::return_level) return true;
        return false;
    }

    // B/C G99 (return to the R level) into system A, which always returns to the initial level
    // (cycles.md §10 "rapid back to the initial level (system A; B/C: G98 initial / G99 R)"): the
    // same motion wherever no drilling cycle under it has an R point off the initial level (R
    // omitted or 0: "distance from the initial level to the R point").
    void scan_return_levels(const ast::Program& p) {
        std::optional<std::uint32_t> open;   // the G99 token of the region
        std::string why;
        bool drilling = false, r_off = false;
        const auto close = [&] {
            if (open) return_level_[*open] = why;
            open.reset();
            why.clear();
        };
        for (std::uint32_t b = p.first_block; b < p.end_block; ++b) {
            if (tree_.blocks[b].kind != ast::BlockKind::code) continue;
            const ast::BlockView view = file_.block(b);
            bool motion_code = false, cycle_block = false, axis = false;
            view.collect_codes(g_, m_);
            for (const ast::CodeRef& c : g_) {
                if (!c.info) continue;
                const FunctionId f = c.info->function;
                if (f == fn::return_initial_level) close();
                if (f == fn::return_r_level) {
                    close();
                    open = c.token;
                }
                if (is_drilling_cycle(f)) cycle_block = true;
                else if (c.info->has(dialects::traits::motion_group) || f == fn::canned_cycle_cancel) motion_code = true;
            }
            axis = !view.axis_words().empty();
            if (cycle_block) {
                drilling = true;
                if (const auto r = view.word('R')) {
                    const Token& t = tree_.tokens[*r];
                    r_off = !t.is_number() || tree_.number_value(t) != 0;
                }
            } else if (motion_code) {
                drilling = false;
            }
            const bool drills = cycle_block || (drilling && !motion_code && axis);
            if (open && drills && r_off && why.empty())
                why = fmt::format("the drilling cycle at line {} returns to its R point under it, {} always returns to the "
                                  "initial level (cycles.md §10)",
                                  line_of(tree_.blocks[b].begin), to_.id);
        }
        close();
    }

    // The dry run: G52 between two readings (the value depends on where the tool is) and --expand.
    void prepare_run() {
        RunRequest request;
        const bool g52_differs = rf_.g52 != rt_.g52 || rf_.g54_cancels_g52 != rt_.g54_cancels_g52;
        for (std::uint32_t b = 0; (g52_differs || options_.expand) && b < tree_.block_count(); ++b) {
            if (tree_.blocks[b].kind != ast::BlockKind::code) continue;
            const ast::BlockView view = file_.block(b);
            LocalEffect effect = LocalEffect::none;
            bool ask = false;
            view.collect_codes(g_, m_);
            for (const ast::CodeRef& c : g_) {
                if (!c.info) continue;
                const FunctionId f = c.info->function;
                if (f == fn::local_system_shift || f == fn::local_system_current_point) effect = LocalEffect::set, ask = true;
                else if (f == fn::local_system_cancel) effect = LocalEffect::cancel, ask = true;
                else if (c.info->work_coordinate() != 0 && rf_.g54_cancels_g52) effect = LocalEffect::cancel, ask = true;
                else if (c.info->work_coordinate() != 0) ask = true;
                else if (f == fn::coordinate_system_setting && rf_.g52 == LocalSystem::vector_shift &&
                         (view.word('X') || view.word('Y') || view.word('Z')))
                    effect = LocalEffect::cancel;
            }
            if (effect != LocalEffect::none) request.local[b] = effect;
            if (ask && g52_differs) request.blocks.push_back(b);
        }
        if (options_.expand) {
            // The first pass finds the constructs; their blocks are asked about too.
            Converter probe(file_, to_, without_expand(options_));
            probe.run();
            for (const std::uint32_t b : probe.expandable_candidates_) request.blocks.push_back(b);
            expandable_ = probe.expandable_candidates_;
            std::sort(request.blocks.begin(), request.blocks.end());
            request.blocks.erase(std::unique(request.blocks.begin(), request.blocks.end()), request.blocks.end());
            request.keep_events = true;
        }
        if (request.blocks.empty()) return;
        const interpreter::Setup setup = options_.setup ? *options_.setup : interpreter::default_setup(from_);
        run_ = SourceRun::run(file_, setup, options_, request);
    }

    static Options without_expand(Options o) {
        o.expand = false;
        return o;
    }

    // --- the pass -----------------------------------------------------------------------------

    // The effective power-on function of a family of functions: the table's default code, else
    // what the interpreter does without one (the first entry: per minute, metric, initial level,
    // the machine kind's plane, no motion).
    static FunctionId power_on_of(const dialects::Dialect& d, std::initializer_list<FunctionId> family, FunctionId none) {
        for (const FunctionId f : family)
            if (power_on(d, f)) return f;
        return none;
    }

    void power_on_differences() {
        const FunctionId plane_default = from_.machine == dialects::MachineKind::lathe ? fn::plane_zx : fn::plane_xy;
        const std::initializer_list<FunctionId> families[] = {
            {fn::feed_per_minute, fn::feed_per_revolution},
            {fn::metric_input, fn::inch_input},
            {fn::plane_xy, fn::plane_zx, fn::plane_yz},
            {fn::return_initial_level, fn::return_r_level},
            {fn::css_off, fn::css_on},
        };
        const FunctionId nones[] = {fn::feed_per_minute, fn::metric_input, plane_default, fn::return_initial_level, fn::css_off};
        for (std::size_t i = 0; i < std::size(families); ++i) {
            const FunctionId s = power_on_of(from_, families[i], nones[i]);
            const FunctionId t = power_on_of(to_, families[i], i == 2 && to_.machine != from_.machine
                                                                    ? (to_.machine == dialects::MachineKind::lathe ? fn::plane_zx : fn::plane_xy)
                                                                    : nones[i]);
            if (s == t) continue;
            if (const CodeInfo* code = codes_.target_code(s)) power_on_codes_.push_back(code);
            else power_on_missing_.push_back(std::string(s.name()));
        }
        source_moves_at_power_on_ = power_on(from_, fn::rapid) || power_on(from_, fn::linear);
        target_moves_at_power_on_ = power_on(to_, fn::rapid) || power_on(to_, fn::linear);
        if (source_moves_at_power_on_) {
            const FunctionId m = power_on(from_, fn::rapid) ? fn::rapid : fn::linear;
            if (!power_on(to_, m)) power_on_motion_ = codes_.target_code(m);
        }
    }

    // The first code block of a program states the source's power-on modes the target lacks.
    void write_power_on(const ast::BlockView& view, std::span<const Token> tokens, bool lower) {
        if (!power_on_pending_ || view.block().kind != ast::BlockKind::code) return;
        power_on_pending_ = false;
        for (const std::string& f : power_on_missing_)
            report(view.range(), ReportKind::unconverted, block_text(view),
                   fmt::format("{} starts in {} mode and {} has no code for it (dialects.md §3.8)", from_.id, f, to_.id));
        for (const CodeInfo* code : power_on_codes_)
            if (!in_same_family(code->function)) insert_code(tokens, *code, lower);
    }

    // A block that sets a mode of the same family (G94 where G95 would go): it states it already.
    bool in_same_family(FunctionId f) const {
        const std::initializer_list<FunctionId> families[] = {
            {fn::feed_per_minute, fn::feed_per_revolution}, {fn::metric_input, fn::inch_input},
            {fn::plane_xy, fn::plane_zx, fn::plane_yz},      {fn::return_initial_level, fn::return_r_level},
            {fn::css_off, fn::css_on},                         {fn::rapid, fn::linear, fn::circular_cw, fn::circular_ccw},
        };
        for (const auto& family : families) {
            if (std::find(family.begin(), family.end(), f) == family.end()) continue;
            for (const CodeInfo* c : infos_)
                if (c && std::find(family.begin(), family.end(), c->function) != family.end()) return true;
            if (f == fn::rapid || f == fn::linear)
                for (const CodeInfo* c : infos_)
                    if (c && c->has(dialects::traits::motion_group)) return true;
        }
        return false;
    }

    // The power-on modes matter in the file's first program, the one a control starts: the others
    // are subprograms and run in their caller's modes.
    void reset_program_state(std::size_t b) {
        const auto& programs = file_.programs();
        in_first_program_ = programs.empty() || b < programs.front().end_block;
        power_on_pending_ = in_first_program_;
        src_incremental_ = src_power_incremental_;
        tgt_incremental_ = tgt_power_incremental_;
        motion_ = nullptr;
        feed_per_rev_ = power_on(from_, fn::feed_per_revolution);
        plane_ = from_.machine == dialects::MachineKind::lathe ? dialects::PlaneTrait::zx : dialects::PlaneTrait::xy;
        for (const CodeInfo& c : from_.codes())
            if (c.power_on_default && c.plane() != dialects::PlaneTrait::none) plane_ = c.plane();
        compensating_ = transformed_ = false;
        seen_motion_ = false;
    }

    void convert_block(std::size_t b) {
        const ast::Block& block = tree_.blocks[b];
        if (block.kind == ast::BlockKind::program_start || b == 0) reset_program_state(b);
        if (block.kind == ast::BlockKind::tail || block.kind == ast::BlockKind::blank || block.kind == ast::BlockKind::percent) return;
        const ast::BlockView view = file_.block(b);
        const auto tokens = view.tokens();
        const std::uint32_t first = view.first_token();
        for (std::uint32_t i = 0; i < tokens.size(); ++i) {
            const Token& t = tokens[i];
            if (t.kind == TokenKind::comment) convert_comment(t);
            else if (t.kind == TokenKind::eob) convert_eob(t);
            else if (t.kind == TokenKind::word && t.role() != Role::none) header_done_ = true;
            if (t.kind == TokenKind::word && t.role() == Role::program) check_program_number(t);
        }
        if (block.kind == ast::BlockKind::code || block.kind == ast::BlockKind::program_start) {
            header_done_ = true;
            if (expandable_.count(static_cast<std::uint32_t>(b)) && try_expand(static_cast<std::uint32_t>(b), view)) {
                flush_block();
                return;
            }
            convert_code_block(static_cast<std::uint32_t>(b), view, first, tokens);
        }
        flush_block();
    }

    // --- comments and block ends (dialects/SCHEMA.md [lexical]) --------------------------------

    enum class CommentForm { paren, semicolon, line };

    // A comment as the target reads it: its text unchanged, or in the target's comment form; nullopt
    // with a report when the target has no form for it.
    struct CommentText {
        std::optional<std::string> text;   // nullopt: as written
        bool parens_replaced = false;
        bool impossible = false;
    };
    CommentText target_comment(std::string_view text) const {
        CommentText r;
        if (text.empty()) return r;
        std::string_view body;
        std::string_view opener;
        CommentForm form = CommentForm::paren;
        if (text.front() != '(') {
            for (const std::string& l : from_.lexical.line_comments)
                if (text.substr(0, l.size()) == l && l.size() > opener.size()) opener = text.substr(0, l.size());
            if (opener.empty() && text.front() == ';') opener = text.substr(0, 1);
            form = opener == ";" && from_.lexical.semicolon == dialects::SemicolonRole::comment ? CommentForm::semicolon
                                                                                                : CommentForm::line;
            body = text.substr(opener.size());
        }
        if (accepts(form, opener)) return r;
        // A ( ) comment into a target without ( ), or no ( ) in the target for a line comment.
        if (form == CommentForm::paren || !to_.lexical.paren_comments) {
            r.impossible = true;
            return r;
        }
        std::string inner(body);
        r.parens_replaced = inner.find_first_of("()") != std::string::npos;
        std::replace(inner.begin(), inner.end(), '(', '[');
        std::replace(inner.begin(), inner.end(), ')', ']');
        // A line comment runs to the end of the line, blanks included; ( ) needs none of them.
        while (!inner.empty() && (inner.back() == ' ' || inner.back() == '\t')) inner.pop_back();
        std::string out = "(";
        out.append(inner);
        out += ')';
        r.text = std::move(out);
        return r;
    }

    void convert_comment(const Token& t) {
        const std::string_view text = spelling(t);
        if (!header_done_) rename_header(t, text);
        const CommentText c = target_comment(text);
        if (c.impossible) {
            report_token(t, ReportKind::unconverted, fmt::format("{} reads no comment of this form", to_.id));
            return;
        }
        if (!c.text) return;
        replace_token(t, *c.text);
        if (c.parens_replaced)
            report_token(t, ReportKind::note,
                         fmt::format("( ) inside the comment became [ ]: {} comments cannot nest (dialects.md §2)", to_.id));
    }

    bool accepts(CommentForm form, std::string_view opener) const {
        switch (form) {
        case CommentForm::paren: return to_.lexical.paren_comments;
        case CommentForm::semicolon: return to_.lexical.semicolon == dialects::SemicolonRole::comment;
        case CommentForm::line:
            return std::find(to_.lexical.line_comments.begin(), to_.lexical.line_comments.end(), opener) !=
                   to_.lexical.line_comments.end();
        }
        return false;
    }

    // `(DIALECT: fanuc-lathe-a)` before the first word names the target (reference/README.md).
    void rename_header(const Token& t, std::string_view text) {
        const std::size_t at = text.find("DIALECT:");
        if (at == std::string_view::npos) return;
        std::size_t begin = at + 8;
        while (begin < text.size() && text[begin] == ' ') ++begin;
        std::size_t end = begin;
        while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-' || text[end] == '+'))
            ++end;
        if (end == begin || text.substr(begin, end - begin) == to_.id) return;
        edit(t.begin + static_cast<std::uint32_t>(begin), t.begin + static_cast<std::uint32_t>(end), to_.id);
    }

    // ';' ends a block in FANUC and starts a comment in pcnc-mill (dialects.md §8): where the target
    // reads it as a comment, a ';' that ends a line goes, one followed by more blocks becomes a line break.
    void convert_eob(const Token& t) {
        if (to_.lexical.semicolon != dialects::SemicolonRole::comment) return;
        const std::string_view text = tree_.text;
        std::uint32_t after = t.begin + t.length;
        while (after < text.size() && (text[after] == ' ' || text[after] == '\t')) ++after;
        const bool line_end = after >= text.size() || text[after] == '\n' || text[after] == '\r';
        replace_token(t, line_end ? std::string() : line_ending_);
    }

    void check_program_number(const Token& t) {
        const int digits = to_.lexical.program_digits;
        if (digits <= 0 || !t.is_number()) return;
        const double v = tree_.number_value(t);
        // Only what the source holds and the target does not: a number too wide for both is the
        // program's own matter.
        const int source = from_.lexical.program_digits;
        if (source > 0 && v >= std::pow(10.0, source)) return;
        if (v >= std::pow(10.0, digits))
            report_token(t, ReportKind::unconverted,
                         fmt::format("{} program numbers have {} digits at most (dialects.md §2)", to_.id, digits));
    }

    // --- code blocks --------------------------------------------------------------------------

    void convert_code_block(std::uint32_t b, const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens) {
        view.collect_codes(g_, m_);
        infos_.clear();
        for (const ast::CodeRef& c : g_) infos_.push_back(c.info);
        for (const ast::CodeRef& c : m_) infos_.push_back(c.info);
        const bool lower = !tokens.empty() && tokens.front().has(ast::token_flags::lower_case);

        bool group01 = false;
        for (const ast::CodeRef& c : g_) {
            if (c.info && (c.info->has(dialects::traits::motion_group) || (c.info->has(dialects::traits::cycle) && c.info->modal)))
                group01 = true;
            convert_code(b, view, c);
        }
        for (const ast::CodeRef& c : m_) convert_code(b, view, c);
        write_power_on(view, tokens, lower);
        report_no_motion_mode(view, group01, tokens, lower);
        convert_distance(b, view, first, tokens, lower);
        convert_parameters(view, first, tokens);
        convert_call(view);
        check_macro(view, tokens);
        report_repeat(b, view, group01);
        update_state(view, group01);
    }

    void convert_code(std::uint32_t b, const ast::BlockView& view, const ast::CodeRef& c) {
        const Token& t = tree_.tokens[c.token];
        if (!c.info) {
            // A code the source does not know reads alike where the target does not know it either
            // (a machine builder's M code): a note. Where the target has the number, it is a hazard.
            if (!c.key) {
                report_token(t, ReportKind::unconverted, "a computed code cannot be converted by meaning: left as it is");
            } else if (to_.code(t.letter, *c.key)) {
                report_token(t, ReportKind::unconverted,
                             fmt::format("not a code of {}: left as it is{}", from_.id, hazard(t.letter, c.key)));
            } else {
                report_token(t, ReportKind::note, fmt::format("a code of neither {} nor {}: left as it is", from_.id, to_.id));
            }
            return;
        }
        const CodeMapping& m = codes_(*c.info);
        switch (m.action) {
        case CodeAction::keep: return;
        case CodeAction::rename:
        case CodeAction::rotation_sign:
            if (m.target->key != c.info->key) replace_token(t, respell(t, *m.target));
            if (m.action == CodeAction::rotation_sign) negate_rotation(view);
            return;
        case CodeAction::local_system:
        case CodeAction::local_cancel: convert_local_system(b, view, c, m); return;
        case CodeAction::distance_mode: return;   // convert_distance
        case CodeAction::return_level: convert_return_level(c); return;
        case CodeAction::none: break;
        }
        if (c.info->function == fn::canned_cycle_cancel && !can_cycle_) {
            remove_token(c.token);
            report_token(t, ReportKind::note,
                         fmt::format("removed: {} has no canned cycles, so there is none to cancel", to_.id));
            return;
        }
        report_token(t, ReportKind::unconverted,
                     fmt::format("{} ({}) has no equivalent in {}: left as it is{}", c.info->spelling, c.info->function,
                                 to_.id, hazard(t.letter, c.key)));
        if (moves(*c.info)) expandable_candidates_.insert(b);
    }

    std::set<std::uint32_t> expandable_candidates_;

    static bool has_canned_cycles(const dialects::Dialect& d) {
        return std::any_of(d.codes().begin(), d.codes().end(), [](const CodeInfo& c) { return is_drilling_cycle(c.function); });
    }

    static bool moves(const CodeInfo& c) {
        return c.has(dialects::traits::cycle) || c.has(dialects::traits::motion_group) || c.function == fn::reference_return ||
               c.function == fn::reference_return_nth || c.function == fn::return_from_reference ||
               c.function == fn::dwell || c.has(dialects::traits::arc_approach) || c.function == fn::axis_homing;
    }

    std::uint32_t token_index(const Token& t) const { return static_cast<std::uint32_t>(&t - tree_.tokens.data()); }

    std::string respell(const Token& t, const CodeInfo& target) const {
        const char letter = t.has(ast::token_flags::lower_case) ? static_cast<char>(std::tolower(t.letter)) : t.letter;
        std::string spelled(1, letter);
        spelled.append(tree_.value_spelling(t));
        return respell_code(spelled, target);
    }

    // G68 R: + = CCW (FANUC) ↔ + = CW (ADV400), gcode-tables.md §8.10: the angle changes sign.
    void negate_rotation(const ast::BlockView& view) {
        const auto r = view.word('R');
        if (!r) return;
        const Token& t = tree_.tokens[*r];
        const auto d = t.is_number() ? parse_decimal(tree_.value_spelling(t)) : std::nullopt;
        if (!d) {
            report_token(t, ReportKind::unconverted, "a G68 angle written as an expression cannot change sign here");
            return;
        }
        rewrite(*r).value = d->point ? with_point(negated(*d)) : plain(negated(*d));
    }

    // B/C G98/G99 (return level) into system A.
    void convert_return_level(const ast::CodeRef& c) {
        const Token& t = tree_.tokens[c.token];
        if (c.info->function == fn::return_initial_level) {
            remove_token(c.token);
            report_token(t, ReportKind::note,
                         fmt::format("removed: {} always returns to the initial level (cycles.md §10)", to_.id));
            return;
        }
        const auto it = return_level_.find(c.token);
        if (it == return_level_.end() || it->second.empty()) {
            remove_token(c.token);
            report_token(t, ReportKind::note,
                         fmt::format("removed: no drilling cycle under it has an R point off the initial level, so {}'s "
                                     "return to the initial level is the same motion (cycles.md §10)",
                                     to_.id));
            return;
        }
        report_token(t, ReportKind::unconverted,
                     fmt::format("{} (return to the R level) has no equivalent in {}: {}; left as it is{}", c.info->spelling,
                                 to_.id, it->second, hazard(t.letter, c.key)));
    }

    // --- G90/G91 and U/W (dialects.md §3.2, §4; gcode-tables.md §1.1) -------------------------

    struct AxisMeaning {
        std::uint32_t token;
        char axis;
        bool incremental;
        bool letter_form;   // written with an incremental letter (U/W/H)
    };
    std::vector<AxisMeaning> axes_;

    // G10 L2 (work offsets) adds its axis words under G91; the lathe's G10 P (work shift, tool
    // offsets) takes only its own U/W as increments (interpreter/executor_data_input.cpp).
    bool data_follows_mode(const ast::BlockView& view) const {
        bool data_input = false;
        for (const CodeInfo* c : infos_)
            if (c && c->function == fn::programmable_data_input) data_input = true;
        if (!data_input) return false;
        const auto l = view.word('L');
        return l && tree_.tokens[*l].is_number() && tree_.number_value(tree_.tokens[*l]) == 2;
    }

    // Codes whose blocks read the same in G90 and G91: their words are no positions (a dwell, a
    // feed or speed mode, a plane, units, a mode that only switches something on or off).
    static bool distance_free(FunctionId f) {
        static constexpr FunctionId kFree[] = {
            fn::dwell, fn::feed_per_minute, fn::feed_per_revolution, fn::css_on, fn::css_off, fn::plane_xy, fn::plane_zx,
            fn::plane_yz, fn::inch_input, fn::metric_input, fn::canned_cycle_cancel, fn::return_initial_level,
            fn::return_r_level, fn::modal_macro_call_cancel, fn::stroke_check_off, fn::tool_length_comp_cancel,
            fn::exact_stop_check, fn::exact_stop_mode, fn::continuous_cutting_mode};
        return std::find(std::begin(kFree), std::end(kFree), f) != std::end(kFree);
    }

    bool dependent(const ast::BlockView& view) const {
        for (const ast::CodeRef& c : g_)
            if (!c.info || !distance_free(c.info->function)) return true;
        for (const ast::CodeRef& c : m_) {
            if (!c.info) continue;
            const FunctionId f = c.info->function;
            if (f == fn::subprogram_call || f == fn::subprogram_return || f == fn::program_end || f == fn::program_end_rewind ||
                c.info->has(dialects::traits::takes_arguments) || c.info->has(dialects::traits::cycle))
                return true;
        }
        (void)view;
        return false;
    }

    void convert_distance(std::uint32_t b, const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens,
                          bool lower) {
        // The source's mode for this block: its own G90/G91 (the last wins), else the modal one.
        std::optional<std::uint32_t> mode_token;
        for (const ast::CodeRef& c : g_) {
            if (!c.info) continue;
            if (c.info->function == fn::absolute_programming) src_incremental_ = false, mode_token = c.token;
            if (c.info->function == fn::incremental_programming) src_incremental_ = true, mode_token = c.token;
        }
        const bool data_mode = data_follows_mode(view);
        axes_.clear();
        for (std::uint32_t i = 0; i < tokens.size(); ++i) {
            const Token& t = tokens[i];
            if (t.kind != TokenKind::word || t.has(ast::token_flags::value_none)) continue;
            const Role r = t.role();
            const char inc_axis = from_.lexical.incremental_axis_of(t.letter);
            if (r == Role::axis_incremental) {
                axes_.push_back({first + i, inc_axis, true, true});
            } else if (r == Role::axis_absolute || (r == Role::parameter && data_mode && (from_.lexical.is_axis(t.letter) || inc_axis))) {
                if (inc_axis) axes_.push_back({first + i, inc_axis, true, true});
                else axes_.push_back({first + i, t.letter, src_modes_ && src_incremental_, false});
            }
        }
        if (unconverted_motion() || repeats_construct(view)) axes_.clear();   // a construct: its words stay
        const bool profile = flags_[b] & kProfile;
        if (!tgt_modes_) {
            for (const ast::CodeRef& c : g_)
                if (c.info && codes_(*c.info).action == CodeAction::distance_mode) remove_token(c.token);
            for (const AxisMeaning& a : axes_) write_axis(a, true);
            return;
        }
        bool any_inc = false, all_inc = !axes_.empty(), any_mode_form = false;
        for (const AxisMeaning& a : axes_) {
            any_inc = any_inc || a.incremental;
            all_inc = all_inc && a.incremental;
            any_mode_form = any_mode_form || (a.incremental && !a.letter_form);
        }
        std::optional<bool> want;   // the target mode the block needs
        bool to_mode_form = false;  // write the letter-form increments as G91 X/Z
        if (profile) {
            // The profile is read in the cycle block's mode: its increments stay letters.
            for (const AxisMeaning& a : axes_) write_axis(a, true);
            if (mode_token) map_mode_token(*mode_token, src_incremental_);
            return;
        }
        const bool src_effective = src_modes_ && src_incremental_;
        if (!axes_.empty()) {
            const bool letters_must_go = (!src_modes_ && options_.incremental == IncrementalStyle::g91) || !letters_exist();
            if (!any_inc) {
                want = false;
            } else if (all_inc && (letters_must_go || any_mode_form)) {
                want = true;   // G91 X/Z (a source's own G91 words stay as they are)
                to_mode_form = letters_must_go;
            } else if (!all_inc) {
                want = false;   // mixed: the increments stay letters, the rest reads absolute
            } else if (dependent(view)) {
                want = src_effective;   // letters only: they read the same in either mode
            }
        } else if (dependent(view)) {
            want = src_effective;
        }
        for (const AxisMeaning& a : axes_) {
            if (to_mode_form && a.letter_form) rename_letter(a, a.axis);
            else write_axis(a, false);
        }
        if (!want) {
            if (mode_token) {
                map_mode_token(*mode_token, src_incremental_);
                tgt_incremental_ = src_incremental_;
            }
            return;
        }
        if (mode_token) {
            map_mode_token(*mode_token, *want);
        } else if (tgt_incremental_ != *want) {
            insert_mode(first, tokens, *want, lower);
        }
        tgt_incremental_ = *want;
    }

    bool letters_exist() const {
        for (const AxisMeaning& a : axes_)
            if (a.letter_form && !target_letter(a.axis)) return false;
        return true;
    }

    char target_letter(char axis) const {
        for (const auto& [letter, moved] : to_.lexical.incremental_letters)
            if (moved == axis) return letter;
        return 0;
    }

    // An axis word as the target writes it where its increments must be letters (system A, a
    // profile, a mixed block): absolute words stay, increments take the target's letter.
    void write_axis(const AxisMeaning& a, bool letters_only) {
        const Token& t = tree_.tokens[a.token];
        if (!a.incremental) return;
        if (a.letter_form && to_.lexical.incremental_axis_of(t.letter) == a.axis) return;   // U stays U
        if (!a.letter_form && !letters_only) return;   // G91 X stays X under G91
        const char letter = target_letter(a.axis);
        if (!letter) {
            report_token(t, ReportKind::unconverted,
                         fmt::format("an incremental {} move here needs an incremental address, and {} has none for {} "
                                     "(dialects.md §3.2, §4)",
                                     a.axis, to_.id, a.axis));
            return;
        }
        rename_letter(a, letter);
    }

    void rename_letter(const AxisMeaning& a, char letter) {
        if (tree_.tokens[a.token].letter != letter) rewrite(a.token).letter = letter;
    }

    void map_mode_token(std::uint32_t token, bool incremental) {
        const Token& t = tree_.tokens[token];
        const CodeInfo* target = incremental ? tgt_inc_code_ : tgt_abs_code_;
        if (!target) return;
        const auto key = dialects::code_key(tree_.number_value(t));
        if (key && *key == target->key) return;
        replace_token(t, respell(t, *target));
    }

    void insert_mode(std::uint32_t first, std::span<const Token> tokens, bool incremental, bool lower) {
        const CodeInfo* target = incremental ? tgt_inc_code_ : tgt_abs_code_;
        if (!target) return;
        insert_code(tokens, *target, lower);
        (void)first;
    }

    void insert_code(std::span<const Token> tokens, const CodeInfo& code_info, bool lower) {
        const CodeInfo* target = &code_info;
        // Before the first word after N (and after a block delete).
        std::uint32_t at = 0;
        for (; at < tokens.size(); ++at) {
            const Token& t = tokens[at];
            if ((t.kind == TokenKind::word && t.role() != Role::sequence) || t.kind == TokenKind::statement) break;
        }
        if (at == tokens.size()) return;
        const Token& t = tokens[at];
        const bool compact = at > 0 && tokens[at - 1].begin + tokens[at - 1].length == t.begin &&
                             tokens[at - 1].kind == TokenKind::word;
        std::string code = target->spelling;
        if (lower) code[0] = static_cast<char>(std::tolower(code[0]));
        edit(t.begin, t.begin, compact ? code : code + " ");
    }

    // --- parameter words: readings, dwell units, drilling letters, words the target lacks ------

    // A block whose motion code the target lacks is a construct left as it is, words and all.
    bool unconverted_motion() const {
        for (const CodeInfo* c : infos_)
            if (c && moves(*c) && codes_(*c).action == CodeAction::none) return true;
        return false;
    }

    void convert_parameters(const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens) {
        if (unconverted_motion() || repeats_construct(view)) return;
        const CodeInfo* drill = nullptr;
        for (const CodeInfo* c : infos_)
            if (c && is_drilling_cycle(c->function)) drill = c;
        const CodeInfo* drill_target = drill ? mapped(*drill) : nullptr;
        for (std::uint32_t i = 0; i < tokens.size(); ++i) {
            const Token& t = tokens[i];
            if (t.kind == TokenKind::comma_word) {
                convert_comma_word(t);
                if (t.letter != 'A') rewrite_reading(t, WordUnit::length);   // ,C ,R: lengths; ,A an angle
                continue;
            }
            if (t.kind != TokenKind::word || t.has(ast::token_flags::value_none)) continue;
            const Role r = t.role();
            if (r == Role::direct_drawing) {
                convert_plain_drawing(t);
                if (t.letter == 'R') rewrite_reading(t, WordUnit::length);   // executor_drawing.cpp: a corner radius
                continue;
            }
            if (is_axis_role(r)) {
                rewrite_reading(t, WordUnit::length);
                continue;
            }
            if (r != Role::parameter) continue;
            const std::size_t reports = out_.reports.size();
            if (drill && drill_target) rename_drill_letter(t, *drill, *drill_target);
            else check_taken(t);
            if (out_.reports.size() != reports) continue;   // reported: left as written
            const WordUnit unit = parameter_unit(t.letter, infos_);
            if (unit == WordUnit::length) rewrite_reading(t, unit);
            if (unit == WordUnit::dwell) rewrite_dwell(t);
        }
        (void)view;
        (void)first;
    }

    const CodeInfo* mapped(const CodeInfo& c) const {
        const CodeMapping& m = codes_(c);
        return m.action == CodeAction::none || m.action == CodeAction::return_level ? nullptr : m.target ? m.target : &c;
    }

    // A word the target's code of the same function does not take (ADV400 G84 Q, the dwell at
    // the R level): reported, left as it is.
    void check_taken(const Token& t) {
        if (t.letter == 'F' || t.letter == 'S' || t.letter == 'T' || t.letter == 'M') return;
        const std::string letter(1, t.letter);
        for (const CodeInfo* c : infos_) {
            if (!c || !c->has(dialects::traits::cycle) || !c->takes_word(letter)) continue;
            const CodeInfo* target = mapped(*c);
            if (target && !target->words.empty() && !target->takes_word(letter))
                report_token(t, ReportKind::unconverted,
                             fmt::format("{} {} has no {} word ({} of {}): left as it is", to_.id, target->spelling,
                                         t.letter, t.letter, c->spelling));
        }
    }

    void rename_drill_letter(const Token& t, const CodeInfo& source, const CodeInfo& target) {
        const DrillLetters s = drill_letters(source), d = drill_letters(target);
        char to = 0;
        if (t.letter == s.peck && s.peck) to = d.peck;
        else if (t.letter == s.repeat && s.repeat) to = d.repeat;
        else {
            check_taken(t);
            return;
        }
        if (!to) {
            report_token(t, ReportKind::unconverted,
                         fmt::format("{} {} has no {} word: left as it is", to_.id, target.spelling,
                                     t.letter == s.peck ? "peck" : "repeat-count"));
            return;
        }
        if (to != t.letter) rewrite(token_index(t)).letter = to;
    }

    // dialects.md §2 "Numbers", §11.9: an integer length is least increments without calculator
    // input; the target gets the value its machine reads the same (a point makes it mm in both).
    void rewrite_reading(const Token& t, WordUnit) {
        if (!lengths_differ_ || !t.is_number() || t.has(ast::token_flags::has_point)) return;
        auto d = parse_decimal(tree_.value_spelling(t));
        if (!d) return;
        if (!rf_.calculator_decimal) d = shifted(*d, -rf_.increment_digits);
        Rewrite& r = rewrite(token_index(t));
        if (!r.value_fixed) r.value = with_point(*d);
    }

    // semantics.md §8.2: G04 P in ms (FANUC) or s (ADV400), and a drilling cycle's dwell P.
    void rewrite_dwell(const Token& t) {
        if (rf_.dwell_p_seconds == rt_.dwell_p_seconds) return;
        const auto d = t.is_number() ? parse_decimal(tree_.value_spelling(t)) : std::nullopt;
        if (!d) {
            report_token(t, ReportKind::unconverted, "a dwell written as an expression cannot change unit here (semantics.md §8.2)");
            return;
        }
        const Decimal v = shifted(*d, rf_.dwell_p_seconds ? 3 : -3);
        rewrite(token_index(t)).value = plain(v);
        if (!rt_.dwell_p_seconds && plain(v).find('.') != std::string::npos)
            report_token(t, ReportKind::note,
                         fmt::format("{} ms has a fraction: a FANUC P takes whole milliseconds (semantics.md §8.2)", plain(v)));
    }

    // ,A ,C ,R direct drawing (dialects.md §2): only where the target has comma words.
    void convert_comma_word(const Token& t) {
        if (to_.lexical.is_comma_word(t.letter)) return;
        report_token(t, ReportKind::unconverted, fmt::format("{} has no ,{} direct-drawing word (dialects.md §2)", to_.id, t.letter));
    }

    // SPINNER plain A/R in G01 blocks (dialects.md §11.4): the target's comma form.
    void convert_plain_drawing(const Token& t) {
        if (to_.lexical.plain_direct_drawing) return;
        if (!to_.lexical.is_comma_word(t.letter)) {
            report_token(t, ReportKind::unconverted,
                         fmt::format("{} has no ,{} direct-drawing word (dialects.md §2, §11.4)", to_.id, t.letter));
            return;
        }
        edit(t.begin, t.begin, ",");
    }

    // --- M98 (dialects.md §3.6) ---------------------------------------------------------------

    void convert_call(const ast::BlockView& view) {
        bool calls = false;
        for (const ast::CodeRef& c : m_) calls = calls || (c.info && c.info->function == fn::subprogram_call);
        if (!calls) return;
        const auto call = view.subprogram_call();
        if (!call) return;
        const dialects::SubprogramCall form = to_.lexical.subprogram_call;
        const Token& p = tree_.tokens[call->p_token];
        const auto l = view.word('L');
        const int digits = to_.lexical.program_digits > 0 ? to_.lexical.program_digits : 4;
        const std::int64_t limit = static_cast<std::int64_t>(std::pow(10.0, digits));
        if (form == dialects::SubprogramCall::p_l) {
            if (!call->packed) return;
            replace_token(p, letter_part(p) + fmt::format("{}", call->program));
            // Compact blocks ("M98P41001") stay compact.
            const std::string gap = p.begin > 0 && (tree_.text[p.begin - 1] == ' ' || tree_.text[p.begin - 1] == '\t') ? " " : "";
            edit(p.begin + p.length, p.begin + p.length,
                 fmt::format("{}{}{}", gap, p.has(ast::token_flags::lower_case) ? 'l' : 'L', call->repeats));
            return;
        }
        if (form == dialects::SubprogramCall::packed || (form == dialects::SubprogramCall::both && l && !call->packed && call->repeats > 1)) {
            if (call->packed || !l) {
                if (call->program >= limit)
                    report_token(p, ReportKind::unconverted,
                                 fmt::format("program {} does not fit the {} digits of {}'s M98 P", call->program, digits, to_.id));
                return;
            }
            if (call->program >= limit || call->repeats > 9999) {
                report_token(p, ReportKind::unconverted,
                             fmt::format("M98 P{} L{} does not fit {}'s packed M98 P (program of {} digits, repeats up to "
                                         "9999; dialects.md §3.6)",
                                         call->program, call->repeats, to_.id, digits));
                return;
            }
            if (form == dialects::SubprogramCall::both) return;   // both forms read: keep P L
            replace_token(p, letter_part(p) + fmt::format("{}{:0{}}", call->repeats > 1 ? fmt::format("{}", call->repeats) : "",
                                                            call->program, call->repeats > 1 ? digits : 1));
            remove_token(*l);
        }
    }

    // Custom Macro B (dialects.md §3.7) in a target without it.
    void check_macro(const ast::BlockView& view, std::span<const Token> tokens) {
        if (to_.lexical.macro_b || !from_.lexical.macro_b) return;
        for (const Token& t : tokens) {
            if (t.kind == TokenKind::statement || (t.kind == TokenKind::word && t.has(ast::token_flags::value_expr))) {
                report(view.range(), ReportKind::unconverted, block_text(view),
                       fmt::format("{} has no Custom Macro B (#variables, expressions, IF/WHILE/GOTO)", to_.id));
                return;
            }
        }
    }

    // Axis words before any motion code: the source has no power-on motion mode and the target
    // moves them at its own (G00): nothing says "do not move" there.
    void report_no_motion_mode(const ast::BlockView& view, bool group01, std::span<const Token> tokens, bool lower) {
        if (group01 || motion_ || seen_motion_ || !in_first_program_) return;
        bool axis = false;
        for (const Token& t : view.tokens()) axis = axis || (t.kind == TokenKind::word && is_axis_role(t.role()));
        if (!axis) return;
        if (power_on_motion_) {   // the source's power-on G00 the target does not start in
            insert_code(tokens, *power_on_motion_, lower);
            seen_motion_ = true;
            return;
        }
        if (source_moves_at_power_on_ || !target_moves_at_power_on_) return;
        for (const Token& t : view.tokens()) {
            if (t.kind != TokenKind::word || !is_axis_role(t.role())) continue;
            report(view.range(), ReportKind::unconverted, block_text(view),
                   fmt::format("axis words before any motion code: {} has no power-on motion mode, {} moves them at its "
                               "own; write the motion code the program means",
                               from_.id, to_.id));
            return;
        }
    }
    bool seen_motion_ = false;

    // A block with axis words and no group-01 code repeats the modal cycle (cycles.md §8, §10).
    bool repeats_construct(const ast::BlockView& view) const {
        if (!motion_ || codes_(*motion_).action != CodeAction::none) return false;
        for (const CodeInfo* c : infos_)
            if (c && (c->has(dialects::traits::motion_group) || (c->has(dialects::traits::cycle) && c->modal))) return false;
        for (const Token& t : view.tokens())
            if (t.kind == TokenKind::word && is_axis_role(t.role())) return true;
        return false;
    }

    void report_repeat(std::uint32_t b, const ast::BlockView& view, bool group01) {
        if (group01 || !repeats_construct(view)) return;
        report(view.range(), ReportKind::unconverted, block_text(view),
               fmt::format("repeats {} of line {}, which has no equivalent in {}", motion_->spelling, line_of(motion_at_), to_.id));
        expandable_candidates_.insert(b);
    }

    void update_state(const ast::BlockView& view, bool group01) {
        for (const ast::CodeRef& c : g_) {
            if (!c.info) continue;
            const CodeInfo& i = *c.info;
            // The modal motion: a group-01 code, or a drilling cycle of its own group (until G80 or
            // a group-01 code cancels it, cycles.md §10, §11).
            const bool modal_cycle = i.has(dialects::traits::cycle) && i.modal;
            if (i.has(dialects::traits::motion_group) || modal_cycle || i.function == fn::canned_cycle_cancel) {
                motion_ = i.function == fn::canned_cycle_cancel ? nullptr : &i;
                seen_motion_ = true;
                motion_at_ = tree_.tokens[c.token].begin;
            }
            if (i.function == fn::feed_per_minute) feed_per_rev_ = false;
            if (i.function == fn::feed_per_revolution) feed_per_rev_ = true;
            if (i.plane() != dialects::PlaneTrait::none) plane_ = i.plane();
            if (i.has(dialects::traits::radius_comp)) compensating_ = i.has(dialects::traits::radius_comp_on);
            if (i.has(dialects::traits::program_transform) || i.has(dialects::traits::plane_transform) ||
                i.function == fn::coordinate_rotation || i.function == fn::coordinate_rotation_cw)
                transformed_ = true;
            if (i.function == fn::coordinate_rotation_cancel) transformed_ = false;
        }
        (void)view;
        (void)group01;
    }

    // --- G52 (semantics.md §2.4) --------------------------------------------------------------

    void convert_local_system(std::uint32_t b, const ast::BlockView& view, const ast::CodeRef& c, const CodeMapping& m) {
        const Token& code = tree_.tokens[c.token];
        const bool differs = rf_.g52 != rt_.g52;
        if (!differs && m.action == CodeAction::local_system) {
            if (m.target->key != c.info->key) replace_token(code, respell(code, *m.target));
            return;
        }
        const BlockRun* run = run_ ? run_->block(b) : nullptr;
        if (!run) {
            report_token(code, ReportKind::unconverted,
                         fmt::format("the {} value depends on where the tool stands, and the dry run never reached this "
                                     "block: left as it is (semantics.md §2.4)",
                                     to_.id));
            return;
        }
        if (run->varies) {
            report_token(code, ReportKind::unconverted,
                         fmt::format("this G52 runs more than once from different points, so no one {} G52 says the same: "
                                     "left as it is (semantics.md §2.4)",
                                     to_.id));
            return;
        }
        const int digits = rt_.increment_digits;
        bool cancel = true;
        for (std::size_t a = 0; a < run->local_after.size(); ++a) cancel = cancel && std::fabs(run->local_after[a]) < 1e-9;
        // The axis words of the block and where they stand.
        std::vector<std::pair<std::uint32_t, std::size_t>> words;   // token, axis index
        for (const std::uint32_t ti : view.words_with_role(Role::axis_absolute)) {
            const auto axis = interpreter::axis_of_letter(tree_.tokens[ti].letter);
            if (axis) words.push_back({ti, static_cast<std::size_t>(*axis)});
        }
        const CodeInfo* cancel_code = codes_.target_code(fn::local_system_cancel);
        if (cancel && cancel_code && rt_.g52 == LocalSystem::current_point_g152) {
            // pcnc-mill: G152 cancels, and G52 X0 Y0 would not.
            replace_token(code, respell(code, *cancel_code));
            // "G52 X0 Y0" → "G152": the words after the code go with the blanks before them.
            const std::uint32_t code_index = token_index(code);
            bool contiguous = !words.empty();
            for (std::size_t k = 0; k < words.size(); ++k) contiguous = contiguous && words[k].first == code_index + 1 + k;
            if (contiguous) {
                const Token& last = tree_.tokens[words.back().first];
                edit(code.begin + code.length, last.begin + last.length, {});
            } else {
                for (const auto& [ti, axis] : words) remove_token(ti);
            }
            return;
        }
        const CodeInfo* g52 = m.target;
        if (m.action == CodeAction::local_cancel) {
            // G152 → G52 with zeros on the axes the shift had (a zero G52 cancels in both other readings).
            std::string text = respell(code, *g52);
            bool any = false;
            for (std::size_t a = 0; a < 3; ++a) {
                if (std::fabs(run->local_before[a]) < 1e-9 || !to_.lexical.is_axis(interpreter::kAxisLetters[a])) continue;
                text += fmt::format(" {}0", interpreter::kAxisLetters[a]);
                any = true;
            }
            if (!any) text += fmt::format(" {}0", to_.lexical.axes.empty() ? 'X' : to_.lexical.axes.front());
            replace_token(code, text);
            return;
        }
        if (g52->key != c.info->key) replace_token(code, respell(code, *g52));
        std::set<std::size_t> written;
        for (const auto& [ti, axis] : words) {
            const Token& t = tree_.tokens[ti];
            const double value = rt_.g52 == LocalSystem::vector_shift ? run->local_after[axis] : (cancel ? 0.0 : run->after[axis]);
            Rewrite& r = rewrite(ti);
            r.value = format_value(value, digits);
            r.value_fixed = true;
            written.insert(axis);
            (void)t;
        }
        // An axis whose shift changed without being written (an ADV400 zero G52 cancels them all).
        std::string extra;
        for (std::size_t a = 0; a < 3; ++a) {
            if (written.count(a) || std::fabs(run->local_after[a] - run->local_before[a]) < 1e-9) continue;
            const double value = rt_.g52 == LocalSystem::vector_shift ? run->local_after[a] : run->after[a];
            extra += fmt::format(" {}{}", interpreter::kAxisLetters[a], format_value(value, digits));
        }
        if (!extra.empty()) edit(code.begin + code.length, code.begin + code.length, extra);
        if (rt_.g52 == LocalSystem::current_point && !cancel) {
            bool zeros = true;
            for (const auto& [ti, axis] : words) zeros = zeros && std::fabs(run->after[axis]) < 0.5 * std::pow(10.0, -digits);
            if (zeros)
                report_token(code, ReportKind::unconverted,
                             fmt::format("the tool stands at the new origin, and a G52 of zeros cancels in {}: left as the "
                                         "values say (semantics.md §2.4)",
                                         to_.id));
        }
    }

    // --- --expand -----------------------------------------------------------------------------

    bool try_expand(std::uint32_t b, const ast::BlockView& view);

    void report_syntax_errors() {
        for (const ast::Diagnostic& d : tree_.diagnostics) {
            if (d.severity != ast::Severity::error) continue;
            report(d.range, ReportKind::syntax_error, std::string(tree_.slice(d.range)),
                   fmt::format("{} [{}]: left as it is", d.message, d.code));
        }
    }

    friend Conversion convert(const ast::TypedFile&, const dialects::Dialect&, const Options&);
};

bool Converter::try_expand(std::uint32_t b, const ast::BlockView& view) {
    const BlockRun* run = run_ ? run_->block(b) : nullptr;
    const std::string construct = block_text(view);
    const auto refuse = [&](const std::string& why) {
        report(view.range(), ReportKind::unconverted, construct, fmt::format("--expand: {}", why));
        return false;
    };
    if (view.block().has(ast::block_flags::deleted)) return refuse("the block is behind a block delete '/'");
    if (!run) return refuse("the dry run never reached this block");
    if (run->varies) return refuse("the block runs more than once, and not the same way each time");
    if (compensating_) return refuse("it runs under G41/G42: its events are tool-centre points");
    if (transformed_) return refuse("it runs under a coordinate transform (rotation, scaling, mirror, polar)");
    if (tgt_incremental_) return refuse("the target is in G91 here");
    // Kept on the comment's line: N and the block's M codes (as the target spells them) before the
    // comment, the block's own comments after it (a line comment runs to the end of the line).
    view.collect_codes(g_, m_);
    std::string prefix, comments;
    const auto tokens = view.tokens();
    for (const Token& t : tokens) {
        if (t.kind == TokenKind::comment) {
            const CommentText c = target_comment(spelling(t));
            if (c.impossible) return refuse("a comment of the block has no form in the target");
            comments += ' ';
            comments.append(c.text ? *c.text : std::string(spelling(t)));
            continue;
        }
        if (t.kind != TokenKind::word) continue;
        if (t.role() == Role::sequence) {
            prefix.append(spelling(t));
            prefix += ' ';
        }
    }
    for (const ast::CodeRef& c : m_) {
        const Token& t = tree_.tokens[c.token];
        const CodeMapping* m = c.info ? &codes_(*c.info) : nullptr;
        if (!m || (m->action != CodeAction::keep && m->action != CodeAction::rename))
            return refuse(fmt::format("its {} has no equivalent either", spelling(t)));
        prefix.append(m->action == CodeAction::rename ? respell(t, *m->target) : std::string(spelling(t)));
        prefix += ' ';
    }
    ExpandContext context{to_, codes_, rt_, false, dialects::PlaneTrait::xy, false, "\n", "", "", ""};
    context.feed_per_rev = feed_per_rev_;
    context.plane = plane_;
    context.lower_case = !tokens.empty() && tokens.front().has(ast::token_flags::lower_case);
    context.line_ending = line_ending_;
    context.prefix = prefix;
    context.suffix = comments;
    context.construct = construct;
    const Expansion e = expand_block(*run, context);
    if (!e.text) return refuse(e.why_not);
    // The block's text but its line break.
    const ast::Range range = view.range();
    std::uint32_t end = range.end;
    while (end > range.begin && (tree_.text[end - 1] == '\n' || tree_.text[end - 1] == '\r')) --end;
    edit(range.begin, end, *e.text);
    report(range, ReportKind::expanded, construct,
           fmt::format("replaced by the motion the dry run computes for it ({} has no equivalent)", to_.id));
    // The block's modal effects as the source had them, for the blocks after it.
    infos_.clear();
    update_state(view, false);
    return true;
}

}  // namespace

Conversion convert(const ast::TypedFile& file, const dialects::Dialect& target, const Options& options) {
    Converter c(file, target, options);
    return c.run();
}

}  // namespace kerf::converter
