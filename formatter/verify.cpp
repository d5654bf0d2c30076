#include "formatter/verify.hpp"

#include "interpreter/trace_compare.hpp"

namespace kerf::formatter {

// The comparison itself is the interpreter's (interpreter/trace_compare.hpp), shared with
// `kerf convert --verify`; the formatter compares everything, both sides in one dialect.
std::optional<std::string> compare_events(const interpreter::Event& a, const interpreter::Event& b) {
    return interpreter::compare_events(a, b, {});
}

VerifyResult verify(const std::string& name, std::string input, std::string output, const VerifyOptions& o) {
    interpreter::TraceSide before{name, std::move(input), o.dialect, o.setup, o.loader};
    interpreter::TraceSide after{name, std::move(output), o.dialect, o.setup, o.loader};
    const interpreter::TraceComparison c = interpreter::compare_runs(std::move(before), std::move(after), {}, o.run);
    VerifyResult result;
    result.events = c.events;
    if (c.difference)
        result.difference = Difference{c.difference->event, c.difference->input_line, c.difference->output_line, c.difference->what};
    if (const std::optional<interpreter::Event>& a = c.stopped_at)
        result.stopped_at = AlarmStop{a->source.line, a->control_alarm ? a->control_alarm : a->code, a->text};
    return result;
}

}  // namespace kerf::formatter
