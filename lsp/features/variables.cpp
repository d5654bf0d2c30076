#include "lsp/features/variables.hpp"

#include <fmt/format.h>

#include "interpreter/macro/variables.hpp"

namespace kerf::lsp {

namespace n = interpreter::macro::numbers;

namespace {

// [FANUC] 0i/16i/18i/30i operator manuals, "System variables" (the ranges interpreter/
// executor_system.cpp implements; the axis order of #5001.. is the machine's).
constexpr SystemVariable kSystem[] = {
    {1000, 1035, "interface signal inputs (read: 0 in a dry run)", "входные сигналы интерфейса (в пробном прогоне 0)"},
    {1100, 1135, "interface signal outputs", "выходные сигналы интерфейса"},
    {2001, 2999, "tool compensation values (lathe: X/Z/R wear and geometry, tip; mill: H and D)",
     "значения коррекций инструмента (токарный: износ и геометрия X/Z/R, вершина; фрезерный: H и D)"},
    {3000, 3000, "#3000 = n (MESSAGE): macro alarm 3000 + n", "#3000 = n (ТЕКСТ): макро-тревога 3000 + n"},
    {3001, 3001, "clock 1 in ms (the dry-run time)", "таймер 1, мс (время пробного прогона)"},
    {3002, 3002, "clock 2 in hours", "таймер 2, часы"},
    {3003, 3003, "single block / FIN wait control", "управление покадровым режимом и ожиданием FIN"},
    {3004, 3004, "feed hold / feed override / exact stop control", "управление остановом подачи, коррекцией и точным остановом"},
    {3005, 3005, "settings", "установки"},
    {3006, 3006, "#3006 = 1 (MESSAGE): stop with a message", "#3006 = 1 (ТЕКСТ): останов с сообщением"},
    {3007, 3007, "mirror image status", "состояние зеркального отображения"},
    {3011, 3011, "date (YYYYMMDD; 0 in a dry run)", "дата (ГГГГММДД; в пробном прогоне 0)"},
    {3012, 3012, "time (HHMMSS; 0 in a dry run)", "время (ЧЧММСС; в пробном прогоне 0)"},
    {3901, 3901, "parts machined", "число обработанных деталей"},
    {3902, 3902, "parts required", "требуемое число деталей"},
    {4001, 4030, "modal G code of group 1..30 before this block (#4001 = group 01)", "модальный G-код группы 1..30 (#4001 = группа 01)"},
    {4102, 4130, "last B D E F H M N O S T value (#4107 D, #4109 F, #4111 H, #4113 M, #4119 S, #4120 T)",
     "последнее значение B D E F H M N O S T (#4107 D, #4109 F, #4111 H, #4113 M, #4119 S, #4120 T)"},
    {5001, 5020, "end point of the last block, per axis (work coordinates)", "конечная точка предыдущего кадра по осям (система заготовки)"},
    {5021, 5040, "current position in machine coordinates, per axis", "текущее положение в системе станка по осям"},
    {5041, 5060, "current position in work coordinates, per axis", "текущее положение в системе заготовки по осям"},
    {5061, 5080, "skip signal position, per axis", "положение по сигналу пропуска по осям"},
    {5081, 5100, "tool offset value, per axis", "величина коррекции инструмента по осям"},
    {5101, 5120, "servo deviation, per axis", "рассогласование сервопривода по осям"},
    {5201, 5220, "external work offset, per axis", "внешнее смещение нуля по осям"},
    {5221, 5240, "G54 work offset, per axis", "смещение нуля G54 по осям"},
    {5241, 5260, "G55 work offset, per axis", "смещение нуля G55 по осям"},
    {5261, 5280, "G56 work offset, per axis", "смещение нуля G56 по осям"},
    {5281, 5300, "G57 work offset, per axis", "смещение нуля G57 по осям"},
    {5301, 5320, "G58 work offset, per axis", "смещение нуля G58 по осям"},
    {5321, 5340, "G59 work offset, per axis", "смещение нуля G59 по осям"},
    {10001, 19999, "tool compensation values (offsets up to 999)", "значения коррекций инструмента (до 999 коррекций)"},
};

}  // namespace

std::span<const SystemVariable> system_variables() { return kSystem; }

const SystemVariable* system_variable(std::int64_t number) {
    for (const SystemVariable& v : kSystem)
        if (number >= v.first && number <= v.last) return &v;
    return nullptr;
}

std::string variable_kind(std::int64_t number, const std::string& language) {
    const bool ru = language == "ru";
    if (number == n::vacant) return ru ? "#0: всегда пустая (vacant), записать нельзя" : "#0: always vacant (null); cannot be assigned";
    if (number >= n::local_first && number <= n::local_last)
        return ru ? "локальная переменная (#1–#33): свой набор на каждом уровне вызова G65/G66; аргументы A→#1, B→#2, C→#3, I→#4 …"
                  : "local variable (#1–#33): one set per G65/G66 call level; arguments A→#1, B→#2, C→#3, I→#4 …";
    if (number >= n::common_cleared_first && number <= n::common_cleared_last)
        return ru ? "общая переменная (#100–#199): общая для всех программ, сбрасывается при выключении (и по RESET)"
                  : "common variable (#100–#199): shared by all programs, cleared at power-off (and at reset)";
    if (number >= n::common_kept_first && number <= n::common_kept_last)
        return ru ? "общая переменная (#500–#999): сохраняется при выключении" : "common variable (#500–#999): kept at power-off";
    if (const SystemVariable* v = system_variable(number))
        return fmt::format("{} (#{}{}): {}", ru ? "системная переменная" : "system variable", v->first,
                           v->last != v->first ? fmt::format("–#{}", v->last) : "", ru ? v->ru : v->en);
    if (number >= n::system_first) return ru ? "системная переменная, которую kerf не знает" : "a system variable kerf does not know";
    return ru ? "номер переменной вне диапазонов FANUC (тревога 115)" : "not a FANUC variable number (alarm 115)";
}

}  // namespace kerf::lsp
