// Static safety rules read in text order with the modal state of the listing (semantics.md §4–§7).
#include "analyzer/rules/common.hpp"
#include "analyzer/rules/expressions.hpp"
#include "interpreter/events.hpp"

namespace kerf::analyzer::rules {

namespace {

using S = Severity;
namespace fn = dialects::functions;

bool active(const BlockContext& b, dialects::FunctionId function) { return b.has_function(function) || b.modal_function(function); }
// A code of the block cuts a thread (G32/G33, G34, G92/G76 and their B/C numbers: traits::threading).
bool threading(const BlockContext& b) {
    for (const ast::CodeRef& c : b.g)
        if (c.info && c.info->has(dialects::traits::threading)) return true;
    return false;
}
const ast::Token* code_with(const BlockContext& b, dialects::FunctionId function) {
    for (const auto* codes : {&b.g, &b.m})
        for (const ast::CodeRef& c : *codes)
            if (c.info && c.info->function == function) return &b.token(c.token);
    return nullptr;
}

// G96 before any G50 S clamp (semantics.md §4.1: SPINNER always programs it before G96).
class CssWithoutClamp : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (b.has_function(fn::coordinate_system_setting) && number_word(b, 'S')) clamped_ = true;
        const ast::Token* css = code_with(b, fn::css_on);
        if (!css || clamped_ || b.has_function(fn::coordinate_system_setting)) return;
        out.report(b.tree().range(*css), "constant surface speed without a spindle clamp (G50 S) before it",
                   "program G50 S<max rpm> in a block before G96: near X0 the rpm climbs to the machine limit");
        clamped_ = true;   // once per file
    }
    void state(StateKey& key) const override { key.add(clamped_); }

private:
    bool clamped_ = false;
};

class ThreadInCss : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (!threading(b) || !active(b, fn::css_on) || b.has_function(fn::css_off)) return;
        out.report(b.tree().range(b.token(b.g.front().token)), "threading in constant surface speed mode (G96)",
                   "switch to G97 with a fixed rpm before threading: the lead needs a constant speed per pass");
    }
};

bool comp_on(const dialects::CodeInfo& c) { return c.has(dialects::traits::radius_comp_on); }

class CompOnArc : public StaticCheck {
public:
    explicit CompOnArc(dialects::FunctionId function) : function_(function) {}
    void block(const BlockContext& b, Reporter& out) override {
        for (const ast::CodeRef& c : b.g) {
            if (!c.info || !(function_.empty() ? comp_on(*c.info) : c.info->function == function_)) continue;
            if (!circular_motion(b)) return;
            out.report(b.tree().range(b.token(c.token)),
                       fmt::format("{} in an arc block: compensation must start and end on G00 or G01",
                                   b.tree().spelling(b.token(c.token))),
                       "start or cancel the compensation on a straight move before or after the arc");
        }
    }
    void state(StateKey&) const override {}   // function_ is the rule's choice, not state

private:
    dialects::FunctionId function_;
};
struct CompStartOnArc : CompOnArc {
    CompStartOnArc() : CompOnArc({}) {}
};
struct CompCancelOnArc : CompOnArc {
    CompCancelOnArc() : CompOnArc(fn::radius_comp_cancel) {}
};

class CompAtEnd : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (!b.has_function(fn::program_end) && !b.has_function(fn::program_end_rewind)) return;
        for (const auto& [group, info] : b.modal)
            if (info && comp_on(*info) && !b.has_function(fn::radius_comp_cancel))
                out.report(block_text_range(b), fmt::format("the program ends with {} still active", info->spelling),
                           "cancel with G40 on a move away from the part before M30");
    }
};

// T0100 on a lathe: tool 1 with offset 0 = no geometry and wear (dialects.md §3.5).
class ToolWithoutOffset : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (b.file.dialect.lexical.tool_word != "mmnn") return;
        const auto t = number_word(b, 'T');
        if (!t || code_parameter(b, 'T')) return;   // G138 T300 is a thrust limit, not a tool (gcode-tables.md §1 G138)
        const std::string_view spelling = b.tree().spelling(b.token(t->token));
        // T0000 written out in the mmnn form (corpus 1002.NC, MANIFEST): station 00, offset 00. A
        // short T0 is the usual offset cancel at the end of a program and is left alone.
        if (t->value == 0 && spelling.size() == 5) {
            out.report(b.tree().range(b.token(t->token)),
                       fmt::format("{} selects no tool station and no offset: what follows runs without geometry or wear offset", spelling),
                       "write the tool and its offset (T0101); cancel an offset with T0 at the end only");
            return;
        }
        if (t->value < 100 || t->value > 9999 || static_cast<std::int64_t>(t->value) % 100 != 0) return;
        out.report(b.tree().range(b.token(t->token)),
                   fmt::format("{} selects tool {} with offset 00: no geometry or wear offset", b.tree().spelling(b.token(t->token)),
                               static_cast<std::int64_t>(t->value) / 100),
                   fmt::format("write T{:02}{:02} (the offset of the tool)", static_cast<std::int64_t>(t->value) / 100,
                               static_cast<std::int64_t>(t->value) / 100));
    }
};

// Mill: G43 H2 after T1 M06 applies the length of another tool. The tool in the spindle is the
// one the last tool change (M06) loaded: a T word alone pre-selects the next tool and leaves the
// spindle's as it is (`T9 M6` then `T1`: T9 still cuts, issue 15), as the interpreter runs it
// (executor_words.cpp: pending_tool_, M06 changes it in).
class LengthOffsetMismatch : public StaticCheck {
public:
    void begin_program(const FileContext&, std::size_t, Reporter&) override {
        selected_.reset();
        spindle_.reset();
    }
    void state(StateKey& key) const override {
        key.add(selected_.has_value());
        key.add(selected_.value_or(0));
        key.add(spindle_.has_value());
        key.add(spindle_.value_or(0));
    }
    void block(const BlockContext& b, Reporter& out) override {
        if (b.file.dialect.lexical.tool_word != "number") return;
        // A T or H past the integers (T5e42 from a fuzzer) is no tool number: casting it would be undefined.
        if (const auto t = number_word(b, 'T')) selected_ = ast::truncated_integer(t->value);
        if (b.has_function(fn::tool_change)) spindle_ = selected_;
        if (!b.has_function(fn::tool_length_comp_plus) && !b.has_function(fn::tool_length_comp_minus)) return;
        const auto h = number_word(b, 'H');
        const std::optional<std::int64_t> length = h ? ast::truncated_integer(h->value) : std::nullopt;
        if (!length || !spindle_ || *length == *spindle_) return;
        out.report(b.tree().range(b.token(h->token)),
                   fmt::format("H{} is not the length of the tool T{} in the spindle", *length, *spindle_),
                   fmt::format("write H{} unless the offset numbering differs on purpose", *spindle_));
    }

private:
    std::optional<std::int64_t> selected_;   // the last T word: the tool the next M06 loads
    std::optional<std::int64_t> spindle_;    // the tool the last M06 loaded
};

// A main program that moves without G20 or G21 runs in whatever unit the control was left in. That
// matters when the program is written in the other unit than the machine's power-on one: an inch
// program (coordinates to 0.0001, the resolution inch posts write) on a machine that starts in mm,
// as CGIP09902.NC and CGIP11719.NC of the corpus (T02 DIA 0.5000 1/2 ENDMILL, X-0.1522; no G20),
// which the dry run and a machine left in G21 read 25.4 times too small (issue 15). A metric program
// on a metric machine is left alone (the seeds never write G21), as is a subprogram (M99: its
// caller's unit) and a program that reads the unit (#4006, or a variable the dialect marks `units`,
// Haas Setting 9 #20009).
class UnitsNotSet : public StaticCheck {
public:
    void begin_program(const FileContext&, std::size_t, Reporter&) override {
        first_move_.reset();
        unit_set_ = reads_unit_ = main_ = false;
        fractional_ = four_places_ = 0;
    }
    void block(const BlockContext& b, Reporter&) override {
        unit_set_ = unit_set_ || b.has_function(fn::inch_input) || b.has_function(fn::metric_input);
        if (unit_set_) return;   // nothing else matters to the program's finding (end_program)
        main_ = main_ || b.has_function(fn::program_end) || b.has_function(fn::program_end_rewind);
        const auto axes = b.view.axis_words();
        if (!first_move_ && !axes.empty()) first_move_ = block_text_range(b);
        for (const ast::AxisWord& a : axes) {
            const std::string_view spelling = b.tree().spelling(b.token(a.token));
            const std::size_t point = spelling.find('.');
            if (point == std::string_view::npos || point + 1 == spelling.size()) continue;
            ++fractional_;
            four_places_ += spelling.size() - point - 1 == 4;
        }
        const ast::SyntaxTree& tree = b.tree();
        block_expressions(tree, b.view, [&](std::int32_t root) {
            walk(tree, root, false, [&](std::int32_t i, bool) {
                const ast::Expr& e = tree.exprs[static_cast<std::size_t>(i)];
                if (e.kind != ast::ExprKind::variable) return;
                const auto n = constant_of(tree, e.a);
                const auto number = n ? ast::truncated_integer(*n) : std::nullopt;
                const dialects::VariableRange* range = number ? b.file.dialect.variable_range(*number) : nullptr;
                reads_unit_ = reads_unit_ || (n && *n == kUnitModal) || (range && range->units);
            });
        }, [](std::int32_t) {});
    }
    void end_program(const FileContext& file, std::size_t, Reporter& out) override {
        if (reported_ || !main_ || unit_set_ || reads_unit_ || !first_move_ || inch_at_power_on(file.dialect)) return;
        // Inch resolution: at least 5 coordinates, a quarter of those with decimals, to 0.0001.
        if (four_places_ < 5 || four_places_ * 4 < fractional_) return;
        reported_ = true;   // once per file
        out.report(*first_move_,
                   fmt::format("the program moves without G20 or G21 and writes {} coordinates to 0.0001, the resolution of "
                               "inch programs: a machine that starts in mm (as this one) reads them 25.4 times too small",
                               four_places_),
                   "program G20 (inch) or G21 (mm) in the safe-start block");
    }
    void state(StateKey& key) const override {
        for (const bool flag : {unit_set_, reads_unit_, main_, reported_, first_move_.has_value()}) key.add(flag);
        key.add(fractional_);
        key.add(four_places_);
    }

private:
    static constexpr int kUnitModal = 4006;   // [FANUC] #4006: the G20/G21 of modal group 06
    // The power-on unit: the dialect's default code of the unit group (G21 on FANUC, semantics.md §1.3).
    static bool inch_at_power_on(const dialects::Dialect& d) {
        for (const dialects::CodeInfo* c : d.codes_with_function(fn::inch_input))
            if (c->power_on_default) return true;
        return false;
    }
    std::optional<ast::Range> first_move_;
    bool unit_set_ = false, reads_unit_ = false, main_ = false, reported_ = false;
    std::size_t fractional_ = 0, four_places_ = 0;
};

// G28 X0 Z0 in absolute mode goes through the work zero (the part) on its way home.
class G28Absolute : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        if (!b.has_function(fn::reference_return) || active(b, fn::incremental_programming)) return;
        for (const ast::AxisWord& a : b.view.axis_words()) {
            if (a.incremental) continue;
            const ast::Token& t = b.token(a.token);
            // A table turning to B0 on its way home moves no tool through the part (O09994 "G28 B0.").
            if (const auto axis = interpreter::axis_of_letter(t.letter); axis && b.file.setup.rotary[static_cast<std::size_t>(*axis)]) continue;
            out.report(b.tree().range(t),
                       fmt::format("G28 in absolute mode moves first to the work position {}: through the part if it is in the way",
                                   b.tree().spelling(t)),
                       b.file.dialect.lexical.incremental_letters.empty()
                           ? "write G91 G28 with 0 for the axis (no intermediate move)"
                           : "write the incremental letter with 0 (G28 U0. W0.)");
            return;
        }
    }
};

class SpindleOverLimit : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        const double limit = b.file.setup.max_rpm;
        // A built-in machine's limit is a guess (machine/data: [inference]): only a machine file's counts.
        if (!b.file.setup.machine_given || limit <= 0) return;
        const auto s = number_word(b, 'S');   // first: most blocks have no S
        if (!s || s->value <= limit || active(b, fn::css_on) || b.has_function(fn::coordinate_system_setting)) return;
        out.report(b.tree().range(b.token(s->token)), fmt::format("S{:g} rpm is over the machine's spindle limit of {:g} rpm", s->value, limit),
                   "lower the speed; the control clamps it or alarms");
    }
};


class CycleParameter : public StaticCheck {
public:
    void block(const BlockContext& b, Reporter& out) override {
        for (const ast::CodeRef& c : b.g) {
            if (!c.info) continue;
            if (c.info->function == fn::dwell)
                for (const char letter : {'X', 'U', 'P'})
                    if (const auto w = number_word(b, letter); w && w->value < 0)
                        out.report(b.tree().range(b.token(w->token)), "negative dwell time", "a dwell time is 0 or more");
            if (c.info->has(dialects::traits::peck))
                if (const auto q = number_word(b, 'Q'); q && q->value <= 0)
                    out.report(b.tree().range(b.token(q->token)), fmt::format("peck depth Q{:g}: must be more than 0", q->value),
                               "give the depth of one peck as a positive Q");
        }
    }
};

}  // namespace

void add_safety(Registry& r) {
    const auto rule = rule_maker(Category::motion);
    r.add(static_rule<CssWithoutClamp>(rule("K5011", "css-without-clamp", S::warning,
        {"G96 constant surface speed with no G50 S spindle clamp before it.",
         "Facing toward X0 the rpm rises to the machine maximum: the part or the chuck may not hold.",
         "G96 S200 M03", "G50 S2500\nG96 S200 M03", "semantics.md §4.1"})));
    r.add(static_rule<ThreadInCss>(rule("K5012", "thread-in-css", S::warning,
        {"Threading (G32, G76, G92) while G96 is active.",
         "The rpm changes with the diameter between passes: the passes do not land in the same groove.",
         "G96 S150\nG76 X18. Z-20. P1000 Q300 F1.5", "G97 S800\nG76 X18. Z-20. P1000 Q300 F1.5", "semantics.md §4.1"})));
    r.add(static_rule<CompStartOnArc>(rule("K5013", "compensation-start-on-arc", S::error,
        {"G41/G42 programmed in an arc block.", "The control raises an alarm or gouges: compensation starts on G00/G01 only.",
         "G02 G41 X20. Z-5. R5.", "G01 G41 X20. Z-1.\nG02 X20. Z-5. R5.", "semantics.md §5, §6"})));
    r.add(static_rule<CompCancelOnArc>(rule("K5016", "compensation-cancel-on-arc", S::error,
        {"G40 programmed in an arc block.", "The control raises an alarm or gouges: compensation ends on G00/G01 only.",
         "G03 G40 X30. Z-10. R5.", "G03 X30. Z-10. R5.\nG00 G40 X40.", "semantics.md §5, §6"})));
    r.add(static_rule<CompAtEnd>(rule("K5017", "compensation-active-at-end", S::warning,
        {"The program ends with G41/G42 still active.",
         "The next program starts with the compensation of this one (or the control alarms at M30).",
         "G42 G01 X20.\nM30", "G42 G01 X20.\nG40 G00 X100.\nM30", "semantics.md §5, §6"})));
    r.add(static_rule<ToolWithoutOffset>(rule("K5018", "tool-without-offset", S::warning,
        {"A lathe tool word with offset 00 (T0100).", "The tool cuts with no geometry or wear offset: off by the tool's length.",
         "T0100", "T0101", "dialects.md §3.5"})));
    r.add(static_rule<UnitsNotSet>(rule("K5024", "units-not-set", S::warning,
        {"A main program that moves without ever programming G20 or G21 (nor reading the unit, #4006) and writes its "
         "coordinates to 0.0001, the resolution of inch programs, for a machine that starts in mm.",
         "The control keeps the unit it was left in: an inch program runs 25.4 times too small on a machine left in "
         "G21, and the dry run reads it in the machine's power-on unit.",
         "G90 G54 G00 X1.5234 Y2.1250\nG01 Z-0.1250 F10.\nX2.5000 Y3.0625\nX0.5000\nM30",
         "G20 G90 G54 G00 X1.5234 Y2.1250\nG01 Z-0.1250 F10.\nX2.5000 Y3.0625\nX0.5000\nM30",
         "corpus CGIP09902.NC (issue 15); semantics.md §1.3 power-on state"})));
    r.add(static_rule<LengthOffsetMismatch>(rule("K5019", "length-offset-mismatch", S::warning,
        {"G43 H with a number other than the tool in the spindle (mills).",
         "The length of another tool is applied: the tool goes too deep or cuts air.", "T1 M06\nG43 H2 Z50.",
         "T1 M06\nG43 H1 Z50.", "semantics.md §7"})));
    r.add(static_rule<G28Absolute>(rule("K5020", "g28-absolute-intermediate", S::warning,
        {"G28 with an intermediate point in absolute work coordinates.",
         "The tool first moves to that work position (G28 X0 Z0: the centre of the part) before going home.",
         "G28 X0. Z0.", "G28 U0. W0.", "semantics.md §2.8"})));
    r.add(static_rule<SpindleOverLimit>(rule("K5021", "spindle-over-limit", S::warning,
        {"A spindle speed over the machine's maximum rpm.", "The control clamps it or alarms; the cut is not what was planned.",
         "G97 S9000 M03", "G97 S3000 M03", "machine/SCHEMA.md; semantics.md §4.1"})));
    r.add(static_rule<CycleParameter>(rule("K5022", "cycle-parameter-out-of-range", S::error,
        {"A cycle or dwell parameter outside its range (negative dwell, peck depth Q of 0 or less).",
         "The control alarms, or the cycle drills in one plunge.", "G83 X0. Z-20. Q0 R1. F0.1", "G83 X0. Z-20. Q3000 R1. F0.1",
         "cycles.md §0; semantics.md §8.2"})));
}

}  // namespace kerf::analyzer::rules
