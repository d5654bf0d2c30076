// Code lens on each program's first line, from the dry run of the same document version: the
// cycle time and tool path of the run (the first program is the one run; its lens counts the
// subprograms it calls), and per tool the time and path length; another program of the file
// gets its own share of the run ("called: 12.5 s"). While the dry run of this version is still
// going, one lens says so.
#include <fmt/format.h>

#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

json::object lens(const Document& doc, ast::Range at, std::string title) {
    return {{"range", range_json(doc, at)}, {"command", json::object{{"title", std::move(title)}, {"command", ""}}}};
}

std::string tools_text(const ProgramRun& r, bool ru) {
    std::string out;
    for (const auto& [tool, time] : r.time_per_tool) {
        const auto len = r.length_per_tool.find(tool);
        out += fmt::format("{}T{} {} / {:.1f} {}", out.empty() ? "" : " · ", tool, duration(time),
                           len == r.length_per_tool.end() ? 0.0 : len->second, ru ? "мм" : "mm");
    }
    return out;
}

}  // namespace

json::value code_lens(const Snapshot& s) {
    const Document& doc = s.document();
    json::array out;
    if (!doc.refused().empty()) return out;
    const bool ru = doc.settings().language == "ru";
    const auto& programs = doc.typed().programs();
    const DryRun* run = s.run();
    for (std::uint32_t p = 0; p < programs.size(); ++p) {
        const ast::Range first = words_range(doc.tree(), programs[p].first_block);
        const ast::Range at{first.begin, first.begin};
        if (!run) {
            if (p == 0) out.push_back(lens(doc, at, ru ? "пробный прогон выполняется…" : "dry run in progress…"));
            continue;
        }
        if (p == 0) {
            const ProgramRun& t = run->total;
            std::string title = fmt::format(fmt::runtime(ru ? "время цикла {} · рабочий ход {:.1f} мм · ускоренный {:.1f} мм{}" : "cycle time {} · feed {:.1f} mm · rapid {:.1f} mm{}"),
                                            duration(t.time_s), t.feed_mm, t.rapid_mm,
                                            run->completed ? "" : (ru ? " (прогон не дошёл до конца)" : " (the run did not reach its end)"));
            out.push_back(lens(doc, at, std::move(title)));
            if (t.time_per_tool.size() > 0) out.push_back(lens(doc, at, tools_text(t, ru)));
            continue;
        }
        const auto it = run->programs.find(p);
        if (it == run->programs.end()) {
            out.push_back(lens(doc, at, ru ? "не вызывается в пробном прогоне" : "not reached by the dry run"));
            continue;
        }
        out.push_back(lens(doc, at, fmt::format(fmt::runtime(ru ? "в прогоне: {} · рабочий ход {:.1f} мм · {}" : "in the run: {} · feed {:.1f} mm · {}"),
                                                duration(it->second.time_s), it->second.feed_mm, tools_text(it->second, ru))));
    }
    return out;
}

}  // namespace kerf::lsp
