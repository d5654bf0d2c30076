#include "analyzer/fix.hpp"

#include <algorithm>

namespace kerf::analyzer {

FixResult apply_fixes(std::string_view text, const std::vector<Finding>& findings) {
    std::vector<const Fix*> fixes;
    for (const Finding& f : findings)
        if (f.fix && !f.fix->edits.empty()) fixes.push_back(&*f.fix);
    std::stable_sort(fixes.begin(), fixes.end(),
                     [](const Fix* a, const Fix* b) { return a->edits.front().range.begin < b->edits.front().range.begin; });
    FixResult result;
    std::vector<TextEdit> edits;
    for (const Fix* fix : fixes) {
        const bool overlaps = std::any_of(fix->edits.begin(), fix->edits.end(), [&](const TextEdit& e) {
            return std::any_of(edits.begin(), edits.end(), [&](const TextEdit& taken) {
                return (e.range.begin < taken.range.end && taken.range.begin < e.range.end) ||
                       (e.range.begin == taken.range.begin && (e.range.size() == 0 || taken.range.size() == 0));
            });
        });
        if (overlaps) {
            ++result.skipped;
            continue;
        }
        edits.insert(edits.end(), fix->edits.begin(), fix->edits.end());
        ++result.applied;
    }
    std::sort(edits.begin(), edits.end(), [](const TextEdit& a, const TextEdit& b) { return a.range.begin < b.range.begin; });
    std::size_t at = 0;
    for (const TextEdit& e : edits) {
        result.text.append(text.substr(at, e.range.begin - at));
        result.text.append(e.replacement);
        at = e.range.end;
    }
    result.text.append(text.substr(at));
    return result;
}

}  // namespace kerf::analyzer
