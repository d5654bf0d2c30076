// What the pass needs to know before it starts: the blocks of each G70–G73 profile, which B/C
// G99 system A can do without, the dry run for G52 and --expand, the power-on modes that differ.
#include "converter/pass.hpp"

#include "interpreter/default_setup.hpp"

namespace kerf::converter::detail {

void Converter::prepare() {
    flags_.assign(tree_.block_count(), 0);
    const bool return_levels = needs_return_level_pass();
    for (const ast::Program& p : file_.programs()) {
        // Only a source with U/W/H letters into a target with G90/G91 treats a profile apart.
        if (!from_.lexical.incremental_letters.empty() && tgt_modes_) mark_profiles(p);
        if (return_levels) scan_return_levels(p);
    }
    prepare_run();
}

// G70–G73 P..Q (cycles.md §1–§4): the cycle reads its profile blocks with the G90/G91 of the
// cycle block (interpreter/executor_cycles.cpp cycle_profile), so their U/W stay U/W.
void Converter::mark_profiles(const ast::Program& p) {
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

bool Converter::needs_return_level_pass() const {
    for (const CodeInfo& c : from_.codes())
        if (codes_(c).action == CodeAction::return_level) return true;
    return false;
}

// B/C G99 (return to the R level) into system A, which always returns to the initial level
// (cycles.md §10 "rapid back to the initial level (system A; B/C: G98 initial / G99 R)"): the
// same motion wherever no drilling cycle under it has an R point off the initial level (R
// omitted or 0: "distance from the initial level to the R point").
void Converter::scan_return_levels(const ast::Program& p) {
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
void Converter::prepare_run() {
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

Options Converter::without_expand(Options o) {
    o.expand = false;
    return o;
}

// The effective power-on function of a family of functions: the table's default code, else
// what the interpreter does without one (the first entry: per minute, metric, initial level,
// the machine kind's plane, no motion).
FunctionId Converter::power_on_of(const dialects::Dialect& d, std::initializer_list<FunctionId> family, FunctionId none) {
    for (const FunctionId f : family)
        if (power_on(d, f)) return f;
    return none;
}

void Converter::power_on_differences() {
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

}  // namespace kerf::converter::detail
