// The function vocabulary's run-time side: names for messages, "did you mean" for load errors, and
// docs/functions.md's tables rendered from the vocabulary and the dialects that use each id.
#include <fmt/format.h>

#include <algorithm>
#include <ostream>
#include <utility>

#include "dialects/dialect.hpp"

namespace kerf::dialects {

std::ostream& operator<<(std::ostream& out, FunctionId f) { return out << f.name(); }

namespace {

// Levenshtein distance, for "did you mean" on a misspelt function id.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

// The trait names of docs/functions.md's last column, in bit order.
constexpr std::pair<std::uint32_t, std::string_view> kTraitNames[] = {
    {traits::cycle, "cycle"},
    {traits::profile_cycle, "profile P/Q labels"},
    {traits::incremental, "incremental"},
    {traits::per_revolution, "feed per revolution"},
    {traits::css, "constant surface speed"},
    {traits::inch, "inch"},
    {traits::position_offset, "position offset"},
    {traits::radius_comp, "radius compensation"},
    {traits::radius_comp_on, "compensation on"},
    {traits::plane_transform, "plane transform"},
    {traits::length_comp, "length compensation"},
    {traits::corner_slowdown, "corner slow-down"},
    {traits::approach_offset, "approach offset"},
    {traits::arc_approach, "arc approach"},
    {traits::program_transform, "programmable transform"},
    {traits::takes_arguments, "macro arguments"},
    {traits::linear, "linear"},
    {traits::calls_subprogram, "subprogram call"},
    {traits::threading, "threading"},
    {traits::peck, "peck Q"},
    {traits::not_in_plane_transform, "not in G112/G107"},
};

std::string trait_text(const FunctionDef& d) {
    std::vector<std::string> names;
    switch (plane_of(d.traits)) {
        case PlaneTrait::xy: names.emplace_back("plane XY"); break;
        case PlaneTrait::zx: names.emplace_back("plane ZX"); break;
        case PlaneTrait::yz: names.emplace_back("plane YZ"); break;
        case PlaneTrait::none: break;
    }
    for (const auto& [bit, name] : kTraitNames)
        if (d.traits & bit) names.emplace_back(name);
    if (d.position_offset != 0) names.push_back(fmt::format("offset {:+d}·D", d.position_offset));
    if (d.work_coordinate != 0) names.push_back(fmt::format("work system {}", d.work_coordinate));
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

// "G70: fanuc-lathe-a, fanuc-lathe-b; G72: fanuc-lathe-c": each spelling (with its aliases) once,
// in the order the dialects are listed, with the dialects that have it.
std::string codes_text(FunctionId f, const std::vector<std::pair<std::string, const Dialect*>>& tables) {
    std::vector<std::pair<std::string, std::vector<std::string>>> spellings;
    for (const auto& [name, d] : tables) {
        for (const CodeInfo& c : d->codes()) {
            if (c.function != f) continue;
            std::string spelling = c.spelling;
            for (const std::string& alias : c.aliases) spelling += "/" + alias;
            auto it = std::find_if(spellings.begin(), spellings.end(), [&](const auto& s) { return s.first == spelling; });
            if (it == spellings.end()) it = spellings.insert(spellings.end(), {spelling, {}});
            if (std::find(it->second.begin(), it->second.end(), name) == it->second.end()) it->second.push_back(name);
        }
    }
    std::string out;
    for (const auto& [spelling, names] : spellings) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        out += fmt::format("{}{}: {}", out.empty() ? "" : "; ", spelling, list);
    }
    return out.empty() ? "(none built in)" : out;
}

}  // namespace

std::optional<std::string_view> closest_name(std::string_view word, std::span<const std::string_view> candidates) {
    std::optional<std::string_view> best;
    std::size_t best_distance = std::max<std::size_t>(3, word.size() / 4) + 1;   // a few typos, not another word
    for (const std::string_view candidate : candidates) {
        const std::size_t distance = edit_distance(word, candidate);
        if (distance < best_distance) {
            best_distance = distance;
            best = candidate;
        }
    }
    return best;
}

std::optional<std::string_view> closest_function_id(std::string_view id) {
    std::vector<std::string_view> ids;
    for (const FunctionDef& d : FunctionId::all()) ids.push_back(d.id);
    return closest_name(id, ids);
}

std::string function_tables_markdown(const Registry& registry) {
    // The dialects as their files define them: bases (and derived dialects) whole, overlays by their own codes.
    std::vector<std::pair<std::string, const Dialect*>> tables;
    for (const std::string& id : registry.ids())
        if (const Dialect* d = registry.find(id); d && d->overlays.empty()) tables.emplace_back(id, d);
    // By id: derived dialects are registered after their bases, the tables list them in name order.
    std::sort(tables.begin(), tables.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const DialectFile& overlay : registry.overlay_files()) tables.emplace_back(overlay.dialect.id, &overlay.dialect);
    std::string out;
    for (const char letter : {'G', 'M'}) {
        out += fmt::format("## {}-code functions\n\n| id | meaning | codes | kerf acts on it as |\n|---|---|---|---|\n", letter);
        for (const FunctionDef& d : FunctionId::all()) {
            if (d.letter != letter) continue;
            const FunctionId f = *FunctionId::find(d.id);
            out += fmt::format("| `{}` | {} | {} | {} |\n", d.id, d.meaning, codes_text(f, tables), trait_text(d));
        }
        if (letter == 'G') out += "\n";
    }
    return out;
}

}  // namespace kerf::dialects
