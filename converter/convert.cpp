// The converter's API (converter/convert.hpp): edits, reports, readings, and convert(), which runs the
// pass (converter/pass.hpp, a file per concern).
#include "converter/convert.hpp"

#include "converter/pass.hpp"

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
    r.rotary.clear();
    for (std::size_t a = 0; a < interpreter::kAxisCount; ++a)
        if (s.rotary[a] && s.axis_order.find(interpreter::kAxisLetters[a]) != std::string::npos) r.rotary += interpreter::kAxisLetters[a];
    r.dwell_p_seconds = s.dwell_p_in_seconds;
    r.g52 = !s.g52_current_point ? LocalSystem::vector_shift
                                 : (s.g52_zeros_cancel ? LocalSystem::current_point : LocalSystem::current_point_g152);
    r.g54_cancels_g52 = s.g54_cancels_g52;
    r.diameter_x = s.diameter_x;
    return r;
}

Conversion convert(const ast::TypedFile& file, const dialects::Dialect& target, const Options& options) {
    detail::Converter c(file, target, options);
    return c.run();
}

}  // namespace kerf::converter
