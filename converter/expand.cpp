#include "converter/expand.hpp"

#include "converter/pass.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "converter/numbers.hpp"
#include "dialects/functions.hpp"

namespace kerf::converter {

namespace fn = dialects::functions;
using interpreter::Event;
using interpreter::EventKind;
using interpreter::kAxisLetters;

namespace {

constexpr int kPositionDigits = 4;   // 0.0001: inside the 0.001 mm the sweep allows (and inch programs)
constexpr int kFeedDigits = 6;

class Writer {
public:
    explicit Writer(const ExpandContext& c) : c_(c) {}

    std::optional<std::string> code(dialects::FunctionId function) const {
        const dialects::CodeInfo* info = c_.codes.target_code(function);
        if (!info) return std::nullopt;
        return cased(info->spelling);
    }
    std::string cased(std::string s) const {
        if (c_.lower_case)
            for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        return s;
    }
    // Appended piecewise: GCC 12 warns falsely on string + string (-Wrestrict, tests/cli/cli_runner.hpp).
    std::string word(char letter, double value, int digits = kPositionDigits) const {
        std::string w = cased(std::string(1, letter));
        w.append(format_value(value, digits));
        return w;
    }

private:
    const ExpandContext& c_;
};

// The plane's two axes (first, second) and their centre letters (semantics.md §3).
struct PlaneAxes {
    std::size_t first, second;
    char i, j;
};
PlaneAxes plane_axes(dialects::PlaneTrait plane) {
    switch (plane) {
    case dialects::PlaneTrait::zx: return {2, 0, 'K', 'I'};
    case dialects::PlaneTrait::yz: return {1, 2, 'J', 'K'};
    default: return {0, 1, 'I', 'J'};
    }
}

std::string comment(const ExpandContext& c, std::string text) {
    std::replace(text.begin(), text.end(), '(', '[');
    std::replace(text.begin(), text.end(), ')', ']');
    for (char& ch : text)
        if (ch == '\n' || ch == '\r') ch = ' ';
    if (c.target.lexical.paren_comments) return "(" + text + ")";
    if (c.target.lexical.semicolon == dialects::SemicolonRole::comment) return ";" + text;
    if (!c.target.lexical.line_comments.empty()) return c.target.lexical.line_comments.front() + text;
    return {};
}

}  // namespace

Expansion expand_block(const BlockRun& run, const ExpandContext& c) {
    Expansion result;
    const Writer w(c);
    const auto refuse = [&](std::string why) {
        result.why_not = std::move(why);
        return result;
    };
    const auto rapid = w.code(fn::rapid), linear = w.code(fn::linear), cw = w.code(fn::circular_cw),
               ccw = w.code(fn::circular_ccw), dwell = w.code(fn::dwell), thread = w.code(fn::thread_cutting),
               per_rev = w.code(fn::feed_per_revolution), per_min = w.code(fn::feed_per_minute);
    if (!rapid || !linear) return refuse(fmt::format("{} has no G00/G01", c.target.id));
    std::vector<std::string> lines;
    std::string last_code;
    std::optional<double> last_feed;
    bool feed_per_rev = c.feed_per_rev;
    const PlaneAxes plane = plane_axes(c.plane);
    for (const Event& e : run.events) {
        std::string line;
        const auto motion_code = [&](const std::string& code) {
            if (code != last_code) line += code;
            last_code = code;
        };
        const auto feed_mode = [&] {
            if (e.feed_per_rev == feed_per_rev) return true;
            const auto& mode = e.feed_per_rev ? per_rev : per_min;
            if (!mode) return false;
            line += *mode;
            feed_per_rev = e.feed_per_rev;
            last_feed.reset();
            return true;
        };
        const auto axes = [&] {
            bool any = false;
            for (std::size_t a = 0; a < e.end.size(); ++a) {
                if (std::fabs(e.end[a] - e.start[a]) < 1e-9) continue;
                if (!line.empty()) line += ' ';
                line.append(w.word(kAxisLetters[a], e.end[a]));
                any = true;
            }
            if (any) return;
            if (!line.empty()) line += ' ';
            line.append(w.word(kAxisLetters[plane.first], e.end[plane.first]));
        };
        const auto feed = [&] {
            if (last_feed && *last_feed == e.feed) return;
            line += ' ';
            line.append(w.word('F', e.feed, kFeedDigits));
            last_feed = e.feed;
        };
        switch (e.kind) {
        case EventKind::rapid:
            motion_code(*rapid);
            axes();
            break;
        case EventKind::linear:
            if (!feed_mode()) return refuse("the target has no code for the feed mode the cycle moves in");
            motion_code(*linear);
            axes();
            feed();
            break;
        case EventKind::arc_cw:
        case EventKind::arc_ccw: {
            if (!e.center) return refuse("an arc without a centre");
            if (!feed_mode()) return refuse("the target has no code for the feed mode the cycle moves in");
            motion_code(e.kind == EventKind::arc_cw ? *cw : *ccw);
            axes();
            const auto offset = [&](std::size_t a) {
                const double d = (*e.center)[a] - e.start[a];
                return a == 0 && c.reading.diameter_x ? d / 2 : d;   // X centres are diameters, I a radius value
            };
            line += ' ';
            line.append(w.word(plane.i, offset(plane.first)));
            line += ' ';
            line.append(w.word(plane.j, offset(plane.second)));
            feed();
            break;
        }
        case EventKind::thread:
            if (!thread) return refuse(fmt::format("{} has no thread cutting code", c.target.id));
            if (e.lead_end != 0 && std::fabs(e.lead_end - e.feed) > 1e-12) return refuse("a variable-lead thread");
            motion_code(*thread);
            axes();
            feed();
            break;
        case EventKind::dwell:
            if (!dwell) return refuse(fmt::format("{} has no dwell code", c.target.id));
            line = *dwell + " " + w.word('X', e.time_s, 3);
            last_code.clear();
            break;
        case EventKind::message:
            if (e.code != 0) return refuse(fmt::format("the cycle issues M{}", e.code));
            continue;   // kerf's own remarks about the run
        case EventKind::feed_mode:
        case EventKind::spindle:
        case EventKind::coolant:
            continue;
        default:
            return refuse(fmt::format("its run has a {} event, which is not plain motion", interpreter::to_string(e.kind)));
        }
        if (!line.empty()) lines.push_back(std::move(line));
    }
    if (lines.empty()) return refuse("the dry run moved nothing in it");
    if (feed_per_rev != c.feed_per_rev) {
        const auto& mode = c.feed_per_rev ? per_rev : per_min;
        if (!mode) return refuse("the target cannot restore the feed mode");
        lines.push_back(*mode);
    }
    std::string text = c.prefix + comment(c, fmt::format("KERF --EXPAND: {}", c.construct)) + c.suffix;
    for (const std::string& l : lines) text += c.line_ending + l;
    result.text = std::move(text);
    return result;
}

}  // namespace kerf::converter

namespace kerf::converter::detail {

// A construct block replaced by its expansion (docs/convert.md "--expand"), or refused with the reason.
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

}  // namespace kerf::converter::detail
