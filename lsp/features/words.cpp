#include "lsp/features/words.hpp"

#include <fmt/format.h>

#include <array>
#include <vector>

#include "dialects/functions.hpp"

namespace kerf::lsp {

namespace fn = dialects::functions;

namespace {

enum class Which { any, first, second };

struct CycleWord {
    dialects::FunctionId function;
    Which which;
    char letter;
    const char* en;
    const char* ru;
};

// reference/cycles.md: the word tables of §1–§8 (FANUC lathe cycles, G-code system A numbers;
// the same functions in B and C). "least increment" words count the input increment (µm in IS-B).
constexpr CycleWord kCycleWords[] = {
    {fn::finishing_cycle, Which::any, 'P', "first block (N) of the finishing profile (cycles.md §1)", "первый кадр (N) чистового контура (cycles.md §1)"},
    {fn::finishing_cycle, Which::any, 'Q', "last block (N) of the finishing profile (cycles.md §1)", "последний кадр (N) чистового контура (cycles.md §1)"},

    {fn::rough_turning_cycle, Which::first, 'U', "depth of cut per pass Δd, radius, no sign (cycles.md §2)", "глубина резания за проход Δd, на радиус, без знака (cycles.md §2)"},
    {fn::rough_turning_cycle, Which::first, 'R', "retract (relief) e after each pass (cycles.md §2)", "отвод e после каждого прохода (cycles.md §2)"},
    {fn::rough_facing_cycle, Which::first, 'W', "depth of cut per pass Δd in Z (cycles.md §3)", "глубина резания за проход Δd по Z (cycles.md §3)"},
    {fn::rough_facing_cycle, Which::first, 'R', "retract (relief) e after each pass (cycles.md §3)", "отвод e после каждого прохода (cycles.md §3)"},
    {fn::pattern_repeating_cycle, Which::first, 'U', "total X relief Δi (stock in X), radius (cycles.md §4)", "общий припуск по X Δi, на радиус (cycles.md §4)"},
    {fn::pattern_repeating_cycle, Which::first, 'W', "total Z relief Δk (stock in Z) (cycles.md §4)", "общий припуск по Z Δk (cycles.md §4)"},
    {fn::pattern_repeating_cycle, Which::first, 'R', "number of roughing passes d (cycles.md §4)", "число черновых проходов d (cycles.md §4)"},
    // The second block of G71/G72/G73 (cycles.md §2 table).
    {fn::rough_turning_cycle, Which::second, 'P', "first block (N) of the finishing profile", "первый кадр (N) контура"},
    {fn::rough_turning_cycle, Which::second, 'Q', "last block (N) of the finishing profile", "последний кадр (N) контура"},
    {fn::rough_turning_cycle, Which::second, 'U', "finishing allowance Δu in X, signed, diameter (cycles.md §2)", "припуск на чистовую обработку Δu по X, со знаком, на диаметр (cycles.md §2)"},
    {fn::rough_turning_cycle, Which::second, 'W', "finishing allowance Δw in Z, signed (cycles.md §2)", "припуск на чистовую обработку Δw по Z, со знаком (cycles.md §2)"},
    {fn::rough_turning_cycle, Which::second, 'F', "roughing feed (F inside the profile is ignored while roughing)", "подача черновых проходов (F внутри контура при черновой обработке не действует)"},
    {fn::rough_turning_cycle, Which::second, 'S', "roughing spindle speed", "скорость шпинделя при черновой обработке"},
    {fn::rough_turning_cycle, Which::second, 'T', "roughing tool", "инструмент черновой обработки"},

    {fn::face_peck_drilling_cycle, Which::first, 'R', "retract e after each peck (cycles.md §5)", "отвод e после каждого шага (cycles.md §5)"},
    {fn::face_peck_drilling_cycle, Which::second, 'X', "X of the last groove (omitted for drilling)", "X последней канавки (при сверлении не задаётся)"},
    {fn::face_peck_drilling_cycle, Which::second, 'U', "X of the last groove, incremental", "X последней канавки, в приращениях"},
    {fn::face_peck_drilling_cycle, Which::second, 'Z', "final depth", "конечная глубина"},
    {fn::face_peck_drilling_cycle, Which::second, 'W', "final depth, incremental", "конечная глубина, в приращениях"},
    {fn::face_peck_drilling_cycle, Which::second, 'P', "X shift Δi between grooves, radius, least increments (cycles.md §5)", "смещение по X Δi между канавками, на радиус, в дискретах (cycles.md §5)"},
    {fn::face_peck_drilling_cycle, Which::second, 'Q', "depth per peck Δk in Z, least increments (cycles.md §5)", "глубина шага Δk по Z, в дискретах (cycles.md §5)"},
    {fn::face_peck_drilling_cycle, Which::second, 'R', "relief Δd at the bottom of each groove (cycles.md §5)", "отвод Δd на дне каждой канавки (cycles.md §5)"},
    {fn::grooving_cycle, Which::first, 'R', "retract e after each peck, along X (cycles.md §6)", "отвод e после каждого шага по X (cycles.md §6)"},
    {fn::grooving_cycle, Which::second, 'X', "groove bottom diameter", "диаметр дна канавки"},
    {fn::grooving_cycle, Which::second, 'U', "groove bottom, incremental", "дно канавки, в приращениях"},
    {fn::grooving_cycle, Which::second, 'Z', "Z of the last plunge", "Z последнего врезания"},
    {fn::grooving_cycle, Which::second, 'W', "Z of the last plunge, incremental", "Z последнего врезания, в приращениях"},
    {fn::grooving_cycle, Which::second, 'P', "depth per peck Δi in X, radius, least increments (cycles.md §6)", "глубина шага Δi по X, на радиус, в дискретах (cycles.md §6)"},
    {fn::grooving_cycle, Which::second, 'Q', "Z shift Δk between plunges, least increments (cycles.md §6)", "смещение по Z Δk между врезаниями, в дискретах (cycles.md §6)"},
    {fn::grooving_cycle, Which::second, 'R', "relief Δd in Z at the groove bottom (cycles.md §6)", "отвод Δd по Z на дне канавки (cycles.md §6)"},

    {fn::multiple_threading_cycle, Which::first, 'P', "mmrraa: finishing passes m, run-out r (0.1 × lead), thread angle a (cycles.md §7)",
     "mmrraa: число чистовых проходов m, сбег r (0,1 шага), угол профиля a (cycles.md §7)"},
    {fn::multiple_threading_cycle, Which::first, 'Q', "minimum cut depth Δdmin, radius, least increments (cycles.md §7)", "минимальная глубина резания Δdmin, на радиус, в дискретах (cycles.md §7)"},
    {fn::multiple_threading_cycle, Which::first, 'R', "finishing allowance d (cycles.md §7)", "припуск на чистовой проход d (cycles.md §7)"},
    {fn::multiple_threading_cycle, Which::second, 'X', "thread root diameter at the end point", "диаметр впадин резьбы в конечной точке"},
    {fn::multiple_threading_cycle, Which::second, 'U', "thread root, incremental", "впадина резьбы, в приращениях"},
    {fn::multiple_threading_cycle, Which::second, 'Z', "thread end point", "конечная точка резьбы"},
    {fn::multiple_threading_cycle, Which::second, 'W', "thread end point, incremental", "конечная точка резьбы, в приращениях"},
    {fn::multiple_threading_cycle, Which::second, 'R', "taper: radius difference start − end (0 = straight)", "конусность: разность радиусов начало − конец (0 — цилиндрическая)"},
    {fn::multiple_threading_cycle, Which::second, 'P', "thread height k, radius, least increments (cycles.md §7)", "высота профиля k, на радиус, в дискретах (cycles.md §7)"},
    {fn::multiple_threading_cycle, Which::second, 'Q', "depth of the first cut Δd, radius, least increments (cycles.md §7)", "глубина первого прохода Δd, на радиус, в дискретах (cycles.md §7)"},
    {fn::multiple_threading_cycle, Which::second, 'F', "lead", "шаг резьбы"},

    {fn::turning_cycle, Which::any, 'R', "taper: radius difference start − end (cycles.md §8.1)", "конусность: разность радиусов (cycles.md §8.1)"},
    {fn::turning_cycle, Which::any, 'F', "cutting feed", "рабочая подача"},
    {fn::thread_cutting_cycle, Which::any, 'R', "taper: radius difference start − end (cycles.md §8.2)", "конусность: разность радиусов (cycles.md §8.2)"},
    {fn::thread_cutting_cycle, Which::any, 'F', "lead", "шаг резьбы"},
    {fn::facing_cycle, Which::any, 'R', "taper in Z (cycles.md §8.3)", "конусность по Z (cycles.md §8.3)"},
    {fn::facing_cycle, Which::any, 'F', "cutting feed", "рабочая подача"},
    {fn::thread_cutting, Which::any, 'F', "lead (cycles.md §9)", "шаг резьбы (cycles.md §9)"},
    {fn::dwell, Which::any, 'X', "dwell time in seconds (semantics.md §8.2)", "время выдержки в секундах (semantics.md §8.2)"},
    {fn::dwell, Which::any, 'U', "dwell time in seconds (semantics.md §8.2)", "время выдержки в секундах (semantics.md §8.2)"},
    {fn::dwell, Which::any, 'P', "dwell time in ms, no decimal point (semantics.md §8.2)", "время выдержки в мс, без точки (semantics.md §8.2)"},
    {fn::circular_cw, Which::any, 'R', "arc radius (negative: the arc over 180°)", "радиус дуги (отрицательный: дуга больше 180°)"},
    {fn::circular_ccw, Which::any, 'R', "arc radius (negative: the arc over 180°)", "радиус дуги (отрицательный: дуга больше 180°)"},
    {fn::subprogram_call, Which::any, 'P', "program to call (packed form: repeats then four digits of program, dialects.md §3.6)",
     "вызываемая программа (упакованная форма: число повторов и четыре цифры программы, dialects.md §3.6)"},
    {fn::subprogram_call, Which::any, 'L', "number of repeats", "число повторов"},
    {fn::subprogram_call, Which::any, 'Q', "sequence number where the called program starts", "номер кадра, с которого начинается вызываемая программа"},
    {fn::subprogram_return, Which::any, 'P', "sequence number of the caller to return to (dialects.md §3.6)", "номер кадра вызывающей программы для возврата (dialects.md §3.6)"},
    {fn::local_subprogram_call, Which::any, 'P', "sequence number of this program to run as a subroutine", "номер кадра этой программы, выполняемой как подпрограмма"},
    {fn::macro_call, Which::any, 'P', "macro program to call (dialects.md §3.7)", "вызываемая макропрограмма (dialects.md §3.7)"},
    {fn::macro_call, Which::any, 'L', "number of repeats", "число повторов"},
    {fn::modal_macro_call, Which::any, 'P', "macro program called after each move (dialects.md §3.7)", "макропрограмма, вызываемая после каждого перемещения (dialects.md §3.7)"},
    {fn::modal_macro_call, Which::any, 'L', "number of repeats", "число повторов"},
    {fn::coordinate_system_setting, Which::any, 'S', "maximum spindle speed (clamp for constant surface speed)", "максимальная скорость шпинделя (ограничение при постоянной скорости резания)"},
    {fn::tool_length_comp_plus, Which::any, 'H', "tool length offset number", "номер коррекции на длину инструмента"},
    {fn::tool_length_comp_minus, Which::any, 'H', "tool length offset number", "номер коррекции на длину инструмента"},
    {fn::radius_comp_left, Which::any, 'D', "radius offset number", "номер коррекции на радиус"},
    {fn::radius_comp_right, Which::any, 'D', "radius offset number", "номер коррекции на радиус"},
};

// Drilling cycles (cycles.md §10–§11; [FANUC] mill G73/G74/G76/G81–G89).
constexpr dialects::FunctionId kDrilling[] = {
    fn::drilling_cycle, fn::drilling_dwell_cycle, fn::peck_drilling_cycle, fn::high_speed_peck_drilling_cycle, fn::tapping_cycle,
    fn::left_hand_tapping_cycle, fn::boring_cycle, fn::boring_dwell_cycle, fn::boring_spindle_stop_cycle,
    fn::boring_manual_retract_cycle, fn::back_boring_cycle, fn::fine_boring_cycle, fn::face_drilling_cycle, fn::face_tapping_cycle,
    fn::face_boring_cycle, fn::side_drilling_cycle, fn::side_tapping_cycle, fn::side_boring_cycle};

struct LetterWord {
    char letter;
    const char* en;
    const char* ru;
};
constexpr LetterWord kDrillingWords[] = {
    {'Z', "hole bottom (cycles.md §10–§11)", "дно отверстия (cycles.md §10–§11)"},
    {'R', "R level: where the feed starts (cycles.md §10–§11)", "уровень R: начало рабочей подачи (cycles.md §10–§11)"},
    {'Q', "depth per peck (or the shift of a boring cycle)", "глубина шага (или смещение в цикле растачивания)"},
    {'P', "dwell at the bottom", "выдержка на дне"},
    {'F', "cutting feed", "рабочая подача"},
    {'K', "number of repeats", "число повторов"},
    {'L', "number of repeats", "число повторов"},
};

// G65 argument specification I: the letter's local variable (dialects.md §3.7).
int argument_variable(char letter) {
    constexpr std::array<std::pair<char, int>, 21> kMap = {{{'A', 1}, {'B', 2}, {'C', 3}, {'I', 4}, {'J', 5}, {'K', 6}, {'D', 7},
                                                            {'E', 8}, {'F', 9}, {'H', 11}, {'M', 13}, {'Q', 17}, {'R', 18}, {'S', 19},
                                                            {'T', 20}, {'U', 21}, {'V', 22}, {'W', 23}, {'X', 24}, {'Y', 25}, {'Z', 26}}};
    for (const auto& [l, n] : kMap)
        if (l == letter) return n;
    return 0;
}

bool has_letter(const ast::BlockView& view, std::initializer_list<char> letters) {
    for (const char l : letters)
        if (view.word(l)) return true;
    return false;
}

// The second block of a two-block cycle: G71–G73 with P/Q, G74–G76 with an end point.
Which which_block(const ast::BlockView& view, dialects::FunctionId function) {
    if (function == fn::rough_turning_cycle || function == fn::rough_facing_cycle || function == fn::pattern_repeating_cycle)
        return has_letter(view, {'P', 'Q'}) ? Which::second : Which::first;
    if (function == fn::face_peck_drilling_cycle || function == fn::grooving_cycle || function == fn::multiple_threading_cycle)
        return has_letter(view, {'X', 'Z', 'U', 'W'}) ? Which::second : Which::first;
    return Which::any;
}

dialects::FunctionId table_function(dialects::FunctionId f) {
    // The second blocks of G72 and G73 read as G71's (cycles.md §3, §4).
    if (f == fn::rough_facing_cycle || f == fn::pattern_repeating_cycle) return fn::rough_turning_cycle;
    return f;
}

std::string letter_meaning(const Document& doc, const ast::Token& t, bool ru) {
    const dialects::LexicalRules& lex = doc.dialect().lexical;
    const char L = t.letter;
    switch (t.role()) {
        case ast::Role::axis_absolute:
            return fmt::format(fmt::runtime(ru ? "ось {}: положение в системе заготовки{} (в приращениях под G91)" : "axis {}: position in work coordinates{} (incremental under G91)"),
                               L, lex.is_diameter(L) ? (ru ? ", на диаметр" : ", diameter") : "");
        case ast::Role::axis_incremental:
            return fmt::format(fmt::runtime(ru ? "перемещение по оси {} в приращениях (система G-кодов A)" : "incremental move of axis {} (G-code system A)"),
                               lex.incremental_axis_of(L));
        case ast::Role::sequence: return ru ? "номер кадра (метка для переходов)" : "sequence number (a label jumps can reach)";
        case ast::Role::program: return ru ? "номер программы" : "program number";
        case ast::Role::direct_drawing:
            return L == 'A' ? (ru ? "угол прямого программирования контура (dialects.md §11.4)" : "direct-drawing angle (dialects.md §11.4)")
                            : (ru ? "радиус скругления угла (dialects.md §11.4)" : "corner radius of direct drawing (dialects.md §11.4)");
        default: break;
    }
    switch (L) {
        case 'F': return ru ? "подача (мм/об под G99/G95, мм/мин под G98/G94)" : "feed (mm/rev under G99/G95, mm/min under G98/G94)";
        case 'S': return ru ? "скорость шпинделя (об/мин; м/мин при постоянной скорости резания G96)" : "spindle speed (rpm; m/min under constant surface speed G96)";
        case 'T':
            return lex.tool_word == "mmnn" ? (ru ? "инструмент и коррекция: T0101 = инструмент 01, коррекция 01" : "tool and offset: T0101 = tool 01, offset 01")
                                           : (ru ? "номер инструмента (смена по M06)" : "tool number (changed by M06)");
        case 'D': return ru ? "номер коррекции на радиус" : "radius offset number";
        case 'H': return ru ? "номер коррекции на длину" : "length offset number";
        case 'I': case 'J': case 'K':
            return fmt::format(fmt::runtime(ru ? "смещение центра дуги по {} от начальной точки" : "arc centre offset along {} from the start point"), L == 'I' ? 'X' : L == 'J' ? 'Y' : 'Z');
        case 'R': return ru ? "радиус дуги, или уровень R цикла" : "arc radius, or the R level of a cycle";
        default: return {};
    }
}

}  // namespace

std::string word_meaning(const Document& doc, std::uint32_t token, const std::string& language) {
    const bool ru = language == "ru";
    const ast::SyntaxTree& tree = doc.tree();
    const ast::Token& t = tree.tokens[token];
    if (t.kind != ast::TokenKind::word) return {};
    const ast::BlockView view = doc.typed().block(doc.block_at(t.begin));
    std::vector<ast::CodeRef> g, m;
    view.collect_codes(g, m);
    for (const auto* codes : {&g, &m}) {
        for (const ast::CodeRef& c : *codes) {
            if (!c.info) continue;
            const dialects::FunctionId f = c.info->function;
            const Which which = which_block(view, f);
            const dialects::FunctionId table = which == Which::second ? table_function(f) : f;
            for (const CycleWord& w : kCycleWords)
                if (w.function == table && w.letter == t.letter && (w.which == Which::any || w.which == which))
                    return fmt::format("{} {}{}{}: {}", t.letter, ru ? "в кадре " : "in a ", c.info->spelling,
                                       which == Which::first ? (ru ? " (первый кадр)" : " first block") : which == Which::second ? (ru ? " (второй кадр)" : " second block") : (ru ? "" : " block"),
                                       ru ? w.ru : w.en);
            for (const dialects::FunctionId d : kDrilling)
                if (d == f)
                    for (const LetterWord& w : kDrillingWords)
                        if (w.letter == t.letter) return fmt::format("{} {}{}{}: {}", t.letter, ru ? "в кадре " : "in a ", c.info->spelling, ru ? "" : " block", ru ? w.ru : w.en);
            if ((f == fn::macro_call || f == fn::modal_macro_call) && t.role() == ast::Role::parameter)
                if (const int n = argument_variable(t.letter))
                    return fmt::format(fmt::runtime(ru ? "{}: аргумент макровызова {} → локальная переменная #{} (dialects.md §3.7)"
                                                       : "{}: argument of the macro call {} → local variable #{} (dialects.md §3.7)"),
                                       t.letter, c.info->spelling, n);
            if ((c.info->parameter_mask >> (t.letter - 'A') & 1u) && t.letter >= 'A' && t.letter <= 'Z')
                return fmt::format(fmt::runtime(ru ? "{}: данные кода {} ({}), не перемещение" : "{}: data of {} ({}), not an axis move"), t.letter,
                                   c.info->spelling, ru && !c.info->ru.empty() ? c.info->ru : c.info->en);
        }
    }
    const std::string generic = letter_meaning(doc, t, ru);
    return generic.empty() ? std::string() : fmt::format("{}: {}", t.letter, generic);
}

std::string value_in_units(const Document& doc, std::uint32_t token, const std::string& language) {
    const ast::SyntaxTree& tree = doc.tree();
    const ast::Token& t = tree.tokens[token];
    if (!t.is_number() || t.has(ast::token_flags::has_point)) return {};
    if (t.role() != ast::Role::axis_absolute && t.role() != ast::Role::axis_incremental) return {};
    const bool ru = language == "ru";
    const double v = tree.number_value(t);
    const interpreter::Setup& setup = doc.settings().setup;
    // reference/dialects.md §2 "Numbers"; machine/SCHEMA.md calculator_decimal, increment.
    if (setup.calculator_decimal)
        return fmt::format(fmt::runtime(ru ? "{}{} = {:g} мм (ввод без точки как в калькуляторе)" : "{}{} = {:g} mm (calculator-type input: no point means mm)"),
                           t.letter, tree.value_spelling(t), v);
    return fmt::format(fmt::runtime(ru ? "{}{} без точки = {:g} × {:g} мм = {:.6g} мм (дискрета ввода)" : "{}{} without a point = {:g} × {:g} mm = {:.6g} mm (least input increment)"),
                       t.letter, tree.value_spelling(t), v, setup.increment_mm, v * setup.increment_mm);
}

}  // namespace kerf::lsp
