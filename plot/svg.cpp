#include "plot/svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <optional>
#include <string_view>
#include <tuple>
#include <vector>

#include "plot/toolpath.hpp"

namespace kerf::plot {

namespace {

// Strokes (the issue: rapids one colour dashed, feeds another solid, arcs like feeds, threads solid
// in a colour of their own).
struct Style {
    const char* name;     // the class attribute and the legend text
    const char* colour;
    double width;
    const char* dash;     // "" = solid
};
constexpr Style kRapid{"rapid", "#d62728", 1.2, "6 4"};
constexpr Style kFeed{"feed", "#1f4e99", 1.6, ""};
constexpr Style kThread{"thread", "#e08a00", 2.2, ""};
constexpr const char* kStartColour = "#2ca02c";
constexpr const char* kEndColour = "#111111";
constexpr const char* kAlarmColour = "#c000c0";
constexpr const char* kCentreLineDash = "14 3 2 3";   // dash-dot: the drafting line type of an axis

// Pixel layout of the picture.
constexpr double kMaxPlotW = 900;   // the drawing area fits in this box, same scale on both axes
constexpr double kMaxPlotH = 640;
constexpr double kMinPlotW = 420;   // a flat or narrow path is padded to this
constexpr double kMinPlotH = 220;
constexpr double kLeft = 76;        // room for the vertical tick labels
constexpr double kTop = 70;         // title, subtitle, vertical axis label
constexpr double kRight = 28;
constexpr double kTickArea = 40;    // tick labels and the horizontal axis label under the plot
constexpr double kRowH = 30;        // the scale bar row and the legend row
constexpr double kGridPx = 50;      // at least this many pixels between grid lines
constexpr double kScaleBarPx = 200; // the scale bar is at most this long
constexpr double kCharPx = 7;       // width of a character at 12 px, for laying out the legend

const Style& style_of(Stroke s) {
    switch (s) {
    case Stroke::rapid: return kRapid;
    case Stroke::thread: return kThread;
    case Stroke::feed: break;
    }
    return kFeed;
}

// Three decimals at most, no trailing zeros, no "-0": compact and stable output.
std::string num(double v) {
    std::string s = fmt::format("{:.3f}", v);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? "0" : s;
}

// A grid or scale value: as many decimals as the step needs (a 0.0002 step needs four), then compact.
std::string label(double v, double step) {
    const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 9);
    std::string s = fmt::format("{:.{}f}", v, decimals);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

std::string xml_escape(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

// The 1-2-5 series (…, 0.5, 1, 2, 5, 10, …): round lengths for the grid and the scale bar.
double decade_of(double v) { return std::pow(10.0, std::floor(std::log10(v))); }

double nice_floor(double limit) {   // the largest 1-2-5 number ≤ limit
    const double decade = decade_of(limit);
    for (const double m : {5.0, 2.0}) if (m * decade <= limit * (1 + 1e-9)) return m * decade;
    return decade;
}

double nice_ceil(double limit) {    // the smallest 1-2-5 number ≥ limit
    const double decade = decade_of(limit);
    for (const double m : {1.0, 2.0, 5.0}) if (m * decade >= limit * (1 - 1e-9)) return m * decade;
    return 10 * decade;
}

// World (program units, v up) to picture pixels (y down), and the picture's size.
struct Layout {
    Box2 world;          // what the plot area shows, margin included
    double scale = 1;    // pixels per unit, the same on both axes
    double plot_w = 0;
    double plot_h = 0;
    double width = 0;
    double height = 0;
    double x(double h) const { return kLeft + (h - world.h_min) * scale; }
    double y(double v) const { return kTop + (world.v_max - v) * scale; }   // SVG's y grows downwards
    double bottom() const { return kTop + plot_h; }
};

// Widens [lo, hi] about its middle to at least `want`.
void widen(double& lo, double& hi, double want) {
    if (hi - lo >= want) return;
    const double mid = (lo + hi) / 2;
    lo = mid - want / 2;
    hi = mid + want / 2;
}

// The box the plot area frames (SvgOptions::frame): the part when there is one, else everything.
bool frames_part(const Toolpath& t, const SvgOptions& o) { return o.frame == Frame::part && !t.part_bounds.empty; }

// `margin`: the part of the framed extent added on every side (more around a part, so the approach
// and retract rapids near it show).
// The picture's width is set once the legend is known (render_svg).
Layout make_layout(Box2 bounds, bool lathe, double margin_fraction) {
    if (lathe) bounds.extend({bounds.h_min, 0});   // the part axis belongs to a lathe picture
    const double extent = std::max(bounds.h_max - bounds.h_min, bounds.v_max - bounds.v_min);
    // A path that is one point on the picture (Z moves seen from above) gets 10 units around it.
    const double margin = extent > 1e-9 ? margin_fraction * extent : 5.0;
    Layout l;
    l.world = {bounds.h_min - margin, bounds.h_max + margin, bounds.v_min - margin, bounds.v_max + margin, false};
    l.scale = std::min(kMaxPlotW / (l.world.h_max - l.world.h_min), kMaxPlotH / (l.world.v_max - l.world.v_min));
    widen(l.world.h_min, l.world.h_max, kMinPlotW / l.scale);
    widen(l.world.v_min, l.world.v_max, kMinPlotH / l.scale);
    l.plot_w = (l.world.h_max - l.world.h_min) * l.scale;
    l.plot_h = (l.world.v_max - l.world.v_min) * l.scale;
    l.height = std::ceil(kTop + l.plot_h + kTickArea + 2 * kRowH + 6);
    return l;
}

using Out = std::back_insert_iterator<std::string>;

void write_header(Out out, double width, double height, const std::string& title, const std::string& subtitle) {
    fmt::format_to(out,
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
                   "font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"12\">\n"
                   "<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
                   "<text x=\"16\" y=\"26\" font-size=\"17\" font-weight=\"bold\">{2}</text>\n"
                   "<text x=\"16\" y=\"46\" fill=\"#555\">{3}</text>\n",
                   num(width), num(height), xml_escape(title), xml_escape(subtitle));
}

std::string subtitle_of(const Toolpath& t, const SvgOptions& o, bool clipped) {
    const bool lathe = o.kind == dialects::MachineKind::lathe;
    std::string s = lathe ? (o.diameter_x ? "lathe, Z-X view, X drawn at the radius" : "lathe, Z-X view") : "mill, X-Y view";
    if (t.inch) s += ", inches (G20)";
    // Lengths in the drawing's unit (the interpreter measures mm).
    const auto length = [&](double mm) { return t.inch ? fmt::format("{:.2f} in", mm / 25.4) : fmt::format("{:.1f} mm", mm); };
    s += fmt::format(" | feed {} | rapid {}", length(t.feed_mm), length(t.rapid_mm));
    if (t.thread_mm > 0) s += fmt::format(" | thread {}", length(t.thread_mm));
    if (t.not_drawn > 0) s += fmt::format(" | the last {} moves are not drawn (the picture is full)", t.not_drawn);
    if (clipped) s += " | framed on the cuts (--frame all)";
    return s;
}

// The multiples of `step` in [lo, hi], as integer multiples (no drift, 0 lands exactly on a line).
// At most 100: far from the origin a tiny step could otherwise stop advancing.
std::vector<double> multiples(double lo, double hi, double step) {
    std::vector<double> out;
    const double first = std::ceil(lo / step);
    for (int i = 0; i < 100 && (first + i) * step <= hi; ++i) out.push_back((first + i) * step);
    return out;
}

// Grid lines every `step` units with their values along the left and bottom edges.
void write_grid(Out out, const Layout& l, double label_factor) {
    const double step = nice_ceil(kGridPx / l.scale);
    std::string labels;
    fmt::format_to(out, "<g class=\"grid\" stroke=\"#e6e6e6\" stroke-width=\"1\">\n");
    for (const double h : multiples(l.world.h_min, l.world.h_max, step)) {
        fmt::format_to(out, "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\"/>\n", num(l.x(h)), num(kTop), num(l.bottom()));
        labels += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", num(l.x(h)),
                              num(l.bottom() + 15), label(h, step));
    }
    for (const double v : multiples(l.world.v_min, l.world.v_max, step)) {
        fmt::format_to(out, "<line x1=\"{0}\" y1=\"{2}\" x2=\"{1}\" y2=\"{2}\"/>\n", num(kLeft), num(kLeft + l.plot_w),
                       num(l.y(v)));
        labels += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n", num(kLeft - 6),
                              num(l.y(v) + 4), label(v * label_factor, step));
    }
    fmt::format_to(out, "</g>\n<g class=\"ticks\" fill=\"#666\" font-size=\"11\">\n{}</g>\n", labels);
    fmt::format_to(out,
                   "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#999\" class=\"frame\" "
                   "data-view=\"{} {} {} {}\"/>\n",
                   num(kLeft), num(kTop), num(l.plot_w), num(l.plot_h), num(l.world.h_min), num(l.world.v_min),
                   num(l.world.h_max), num(l.world.v_max));
}

// What is cut off at the frame's edge is hidden by this clip path (SvgOptions::frame).
void write_clip(Out out, const Layout& l) {
    fmt::format_to(out, "<clipPath id=\"plot-area\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n",
                   num(kLeft), num(kTop), num(l.plot_w), num(l.plot_h));
}

// Lathes: the part axis (X0) as a centre line across the plot.
void write_part_axis(Out out, const Layout& l) {
    const std::string y = num(l.y(0));
    fmt::format_to(out,
                   "<line class=\"part-axis\" x1=\"{0}\" y1=\"{2}\" x2=\"{1}\" y2=\"{2}\" stroke=\"#555\" "
                   "stroke-width=\"1\" stroke-dasharray=\"{3}\"/>\n"
                   "<text x=\"{4}\" y=\"{5}\" text-anchor=\"end\" fill=\"#555\" font-size=\"11\">part axis</text>\n",
                   num(kLeft), num(kLeft + l.plot_w), y, kCentreLineDash, num(kLeft + l.plot_w - 4), num(l.y(0) - 4));
}

void write_axis_labels(Out out, const Layout& l, const SvgOptions& o) {
    const bool lathe = o.kind == dialects::MachineKind::lathe;
    const char* horizontal = lathe ? "Z \u2192" : "X \u2192";
    const char* vertical = lathe ? (o.diameter_x ? "\u2191 X (values are diameters, drawn at the radius)" : "\u2191 X")
                                 : "\u2191 Y";
    fmt::format_to(out, "<text x=\"{}\" y=\"{}\" text-anchor=\"end\" font-weight=\"bold\">{}</text>\n",
                   num(kLeft + l.plot_w), num(l.bottom() + 32), horizontal);
    fmt::format_to(out, "<text x=\"{}\" y=\"{}\" font-weight=\"bold\">{}</text>\n", num(kLeft), num(kTop - 8), vertical);
}

std::string svg_point(const Layout& l, Point p) { return num(l.x(p.h)) + " " + num(l.y(p.v)); }

// SVG's y axis points down, so an arc that is clockwise as seen (negative sweep with v up) runs in
// SVG's positive-angle direction: sweep-flag 1. G02 is clockwise as seen in both views
// (semantics.md §3; plot/toolpath.hpp), so G02 gets 1 and G03 gets 0.
void append_arc(std::string& d, const Piece& p, const Layout& l) {
    const std::string r = num(p.radius * l.scale);
    const int sweep_flag = p.sweep < 0 ? 1 : 0;
    const auto arc_to = [&](Point q) { d += fmt::format(" A{0} {0} 0 0 {1} {2}", r, sweep_flag, svg_point(l, q)); };
    // Over 180° the arc is drawn in two halves: a full circle cannot be one SVG arc (its ends
    // coincide), and with halves of at most 180° the large-arc flag is always 0.
    if (std::fabs(p.sweep) > std::numbers::pi) arc_to(p.mid);
    arc_to(p.to);
}

void append_piece(std::string& d, const Piece& p, const Layout& l) {
    if (p.arc) return append_arc(d, p, l);
    d += " L" + svg_point(l, p.to);
}

void write_path(Out out, Stroke stroke, const std::string& d) {
    const Style& s = style_of(stroke);
    const std::string dash = *s.dash ? fmt::format(" stroke-dasharray=\"{}\"", s.dash) : "";
    fmt::format_to(out,
                   "<path class=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{} stroke-linejoin=\"round\" "
                   "stroke-linecap=\"round\" d=\"{}\"/>\n",
                   s.name, s.colour, num(s.width), dash, d);
}

bool same_point(Point a, Point b) { return std::fabs(a.h - b.h) <= 1e-6 && std::fabs(a.v - b.v) <= 1e-6; }

// The segment from `a` to `b` clipped to the box (Liang–Barsky): the parameters [t0, t1] of the part
// inside it, or nullopt when none is.
std::optional<std::pair<double, double>> clip(Point a, Point b, const Box2& box) {
    double t0 = 0, t1 = 1;
    const double d[2] = {b.h - a.h, b.v - a.v};
    const double lo[2] = {box.h_min - a.h, box.v_min - a.v};
    const double hi[2] = {box.h_max - a.h, box.v_max - a.v};
    for (int i = 0; i < 2; ++i) {
        if (d[i] == 0) {
            if (lo[i] > 0 || hi[i] < 0) return std::nullopt;
            continue;
        }
        double enter = lo[i] / d[i], leave = hi[i] / d[i];
        if (enter > leave) std::swap(enter, leave);
        t0 = std::max(t0, enter);
        t1 = std::min(t1, leave);
        if (t0 > t1) return std::nullopt;
    }
    return std::pair{t0, t1};
}

bool inside(const Box2& box, Point p) {
    return p.h >= box.h_min && p.h <= box.h_max && p.v >= box.v_min && p.v <= box.v_max;
}

// A rapid that leaves the framed part: where it crosses the frame and where it goes.
struct Exit {
    Point at;
    Point to;
};

// What the picture shows inside its frame; the legend lists these and nothing else.
struct Shown {
    bool rapid = false;
    bool feed = false;
    bool arc = false;
    bool thread = false;
    bool start = false;
    bool end = false;
    bool alarm = false;
    bool clipped = false;      // some of the path or a marker lies outside the frame
    std::vector<Exit> exits;   // one per place and direction (at most kMaxExits)
};

constexpr std::size_t kMaxExits = 100;

// The rapid piece's exit from the frame, if it leaves it (an arc never is a rapid).
void add_exit(Shown& shown, const Piece& p, const std::pair<double, double>& in, const Layout& l,
              std::vector<std::tuple<long, long, long>>& seen) {
    if (in.second >= 1 - 1e-9 || shown.exits.size() >= kMaxExits) return;
    const Point at{p.from.h + in.second * (p.to.h - p.from.h), p.from.v + in.second * (p.to.v - p.from.v)};
    // Arrows that would sit on one another (every tool's G28 home return from one corner) are one.
    const double angle = std::atan2(p.to.v - p.from.v, p.to.h - p.from.h);
    const std::tuple<long, long, long> key{std::lround(l.x(at.h) / 6), std::lround(l.y(at.v) / 6),
                                           std::lround(angle / (std::numbers::pi / 12))};
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) return;
    seen.push_back(key);
    shown.exits.push_back({at, p.to});
}

Shown what_is_shown(const Toolpath& t, const Layout& l) {
    Shown shown;
    std::vector<std::tuple<long, long, long>> seen;
    for (const Piece& p : t.pieces) {
        // Arcs lie inside the frame or not as their box does: only the part's moves are arcs, and
        // the frame holds the part.
        const std::optional<std::pair<double, double>> in =
            p.arc ? std::optional{std::pair{0.0, 1.0}} : clip(p.from, p.to, l.world);
        if (!in) continue;
        switch (p.stroke) {
        case Stroke::rapid:
            shown.rapid = true;
            add_exit(shown, p, *in, l, seen);
            break;
        case Stroke::feed:
            shown.feed = true;
            shown.arc = shown.arc || p.arc;
            break;
        case Stroke::thread: shown.thread = true; break;
        }
    }
    shown.start = t.moves > 0 && inside(l.world, t.start);
    shown.end = t.moves > 0 && inside(l.world, t.end);
    shown.alarm = std::any_of(t.alarms.begin(), t.alarms.end(), [&](Point a) { return inside(l.world, a); });
    // The box of the whole path holds every piece and marker: inside the frame, nothing is cut off.
    shown.clipped = !(inside(l.world, {t.bounds.h_min, t.bounds.v_min}) && inside(l.world, {t.bounds.h_max, t.bounds.v_max}));
    return shown;
}

// One <path> per run of moves with the same stroke, in execution order.
void write_paths(Out out, const Toolpath& t, const Layout& l) {
    std::string d;
    Stroke current = Stroke::feed;
    Point last;
    for (const Piece& p : t.pieces) {
        if (!d.empty() && p.stroke != current) {
            write_path(out, current, d);
            d.clear();
        }
        if (d.empty() || !same_point(last, p.from)) d += (d.empty() ? "M" : " M") + svg_point(l, p.from);
        append_piece(d, p, l);
        current = p.stroke;
        last = p.to;
    }
    if (!d.empty()) write_path(out, current, d);
}

void start_marker(Out out, double x, double y) {
    fmt::format_to(out, "<circle class=\"start\" cx=\"{}\" cy=\"{}\" r=\"5\" fill=\"{}\" stroke=\"white\"/>\n", num(x),
                   num(y), kStartColour);
}

// A hollow square, larger than the start dot: a program that ends where it started shows both.
void end_marker(Out out, double x, double y) {
    fmt::format_to(out,
                   "<rect class=\"end\" x=\"{}\" y=\"{}\" width=\"12\" height=\"12\" fill=\"none\" stroke=\"{}\" "
                   "stroke-width=\"2\"/>\n",
                   num(x - 6), num(y - 6), kEndColour);
}

void alarm_marker(Out out, double x, double y) {
    fmt::format_to(out,
                   "<path class=\"alarm\" d=\"M{0} {1} l10 10 m0 -10 l-10 10\" stroke=\"{2}\" stroke-width=\"2.5\" "
                   "fill=\"none\"/>\n",
                   num(x - 5), num(y - 5), kAlarmColour);
}

// An arrowhead in the rapid colour whose tip is (x, y), pointing along (dx, dy) in pixels; `title`
// (the tooltip) says where the rapid goes.
void exit_arrow(Out out, double x, double y, double dx, double dy, const std::string& title) {
    const double len = std::hypot(dx, dy);
    const double ux = len > 0 ? dx / len : 1, uy = len > 0 ? dy / len : 0;
    const auto corner = [&](double side) {
        return fmt::format("{} {}", num(x - 11 * ux + side * 5 * uy), num(y - 11 * uy - side * 5 * ux));
    };
    fmt::format_to(out, "<path class=\"leaves\" d=\"M{} {} L{} L{} Z\" fill=\"{}\" stroke=\"none\">{}</path>\n", num(x),
                   num(y), corner(1), corner(-1), kRapid.colour,
                   title.empty() ? std::string() : "<title>" + xml_escape(title) + "</title>");
}

// Where a rapid that leaves the frame goes, as programmed (lathe X as a diameter).
std::string destination(Point to, const SvgOptions& o) {
    const bool lathe = o.kind == dialects::MachineKind::lathe;
    if (lathe) return fmt::format("rapid to Z{} X{}", num(to.h), num(o.diameter_x ? 2 * to.v : to.v));
    return fmt::format("rapid to X{} Y{}", num(to.h), num(to.v));
}

// Alarms last: a run stopped by an alarm ends where the alarm is, and the cross must stay visible.
// Markers outside the frame are not drawn.
void write_markers(Out out, const Toolpath& t, const Layout& l, const Shown& shown, const SvgOptions& o) {
    for (const Exit& e : shown.exits)
        exit_arrow(out, l.x(e.at.h), l.y(e.at.v), l.x(e.to.h) - l.x(e.at.h), l.y(e.to.v) - l.y(e.at.v), destination(e.to, o));
    if (shown.start) start_marker(out, l.x(t.start.h), l.y(t.start.v));
    if (shown.end) end_marker(out, l.x(t.end.h), l.y(t.end.v));
    for (const Point& a : t.alarms)
        if (inside(l.world, a)) alarm_marker(out, l.x(a.h), l.y(a.v));
}

// A bar of a round length (1-2-5 series) with end ticks, under the plot on the left.
void write_scale_bar(Out out, const Layout& l, bool inch) {
    const double length = nice_floor(kScaleBarPx / l.scale);
    const double px = length * l.scale;
    const double y = l.bottom() + kTickArea + 10;
    fmt::format_to(out,
                   "<g class=\"scale\"><path d=\"M{0} {2} v-8 v4 h{1} v4 v-8\" fill=\"none\" stroke=\"black\" "
                   "stroke-width=\"1.5\"/>\n<text x=\"{3}\" y=\"{4}\">{5} {6}</text></g>\n",
                   num(kLeft), num(px), num(y), num(kLeft + px + 8), num(y), label(length, length), inch ? "in" : "mm");
}

struct LegendItem {
    const char* label;
    void (*sample)(Out out, double x, double y);   // draws the symbol centred at (x + 15, y)
};

void line_sample(Out out, const Style& s, double x, double y) {
    const std::string dash = *s.dash ? fmt::format(" stroke-dasharray=\"{}\"", s.dash) : "";
    fmt::format_to(out, "<line x1=\"{0}\" y1=\"{2}\" x2=\"{1}\" y2=\"{2}\" stroke=\"{3}\" stroke-width=\"{4}\"{5}/>\n",
                   num(x), num(x + 30), num(y), s.colour, num(s.width), dash);
}

void rapid_sample(Out o, double x, double y) { line_sample(o, kRapid, x, y); }
void feed_sample(Out o, double x, double y) { line_sample(o, kFeed, x, y); }

// The entries of what the drawing contains, in this order.
std::vector<LegendItem> legend_of(const Shown& shown) {
    std::vector<LegendItem> items;
    if (shown.rapid) items.push_back({"rapid", rapid_sample});
    if (!shown.exits.empty())
        items.push_back({"rapid leaving the frame", [](Out o, double x, double y) { exit_arrow(o, x + 22, y, 1, 0, ""); }});
    if (shown.feed) items.push_back({shown.arc ? "feed (lines, arcs)" : "feed", feed_sample});
    if (shown.thread) items.push_back({"thread", [](Out o, double x, double y) { line_sample(o, kThread, x, y); }});
    if (shown.start) items.push_back({"start", [](Out o, double x, double y) { start_marker(o, x + 15, y); }});
    if (shown.end) items.push_back({"end", [](Out o, double x, double y) { end_marker(o, x + 15, y); }});
    if (shown.alarm) items.push_back({"alarm", [](Out o, double x, double y) { alarm_marker(o, x + 15, y); }});
    return items;
}

// The width of a line of 12 px text: kCharPx per character (UTF-8 continuation bytes are no character).
double text_width(std::string_view text) {
    return kCharPx * static_cast<double>(std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

double item_width(const LegendItem& item) { return 30 + 8 + text_width(item.label) + 18; }

double legend_width(const std::vector<LegendItem>& items) {
    double w = 0;
    for (const LegendItem& item : items) w += item_width(item);
    return w;
}

void write_legend(Out out, const std::vector<LegendItem>& items, const Layout& l) {
    const double y = l.bottom() + kTickArea + kRowH + 10;
    double x = kLeft;
    fmt::format_to(out, "<g class=\"legend\">\n");
    for (const LegendItem& item : items) {
        item.sample(out, x, y);
        fmt::format_to(out, "<text x=\"{}\" y=\"{}\">{}</text>\n", num(x + 38), num(y + 4), item.label);
        x += item_width(item);
    }
    fmt::format_to(out, "</g>\n");
}

std::string no_motion_svg(const SvgOptions& o) {
    std::string svg;
    write_header(std::back_inserter(svg), 480, 140, o.title, "");
    svg += "<text x=\"240\" y=\"96\" text-anchor=\"middle\" font-size=\"16\" fill=\"#555\">no motion</text>\n</svg>\n";
    return svg;
}

}  // namespace

std::string render_svg(const std::vector<interpreter::Event>& events, const SvgOptions& options) {
    return render_svg(build_toolpath(events, {options.kind, options.diameter_x, options.frame}), options);
}

std::string render_svg(const Toolpath& t, const SvgOptions& options) {
    if (t.bounds.empty) return no_motion_svg(options);
    const bool lathe = options.kind == dialects::MachineKind::lathe;
    const bool part = frames_part(t, options);
    Layout l = make_layout(part ? t.part_bounds : t.bounds, lathe, part ? 0.1 : 0.05);
    const Shown shown = what_is_shown(t, l);
    const std::vector<LegendItem> legend = legend_of(shown);
    const std::string subtitle = subtitle_of(t, options, shown.clipped);
    // As wide as the plot, the legend and the subtitle (a narrow part with a long subtitle).
    l.width = std::ceil(std::max(kLeft + std::max(l.plot_w, legend_width(legend)) + kRight, text_width(subtitle) + 32));
    std::string svg;
    svg.reserve(4096 + 64 * t.pieces.size());
    const Out out = std::back_inserter(svg);
    write_header(out, l.width, l.height, options.title, subtitle);
    write_grid(out, l, lathe && options.diameter_x ? 2.0 : 1.0);   // lathe X ticks read as programmed: diameters
    if (shown.clipped) write_clip(out, l);
    if (lathe) write_part_axis(out, l);
    write_axis_labels(out, l, options);
    if (shown.clipped) svg += "<g clip-path=\"url(#plot-area)\">\n";
    write_paths(out, t, l);
    if (shown.clipped) svg += "</g>\n";
    write_markers(out, t, l, shown, options);
    write_scale_bar(out, l, t.inch);
    write_legend(out, legend, l);
    svg += "</svg>\n";
    return svg;
}

}  // namespace kerf::plot
