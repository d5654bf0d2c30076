#include "plot/svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
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

Layout make_layout(Box2 bounds, bool lathe, double legend_w) {
    if (lathe) bounds.extend({bounds.h_min, 0});   // the part axis belongs to a lathe picture
    const double extent = std::max(bounds.h_max - bounds.h_min, bounds.v_max - bounds.v_min);
    // A path that is one point on the picture (Z moves seen from above) gets 10 units around it.
    const double margin = extent > 1e-9 ? 0.05 * extent : 5.0;
    Layout l;
    l.world = {bounds.h_min - margin, bounds.h_max + margin, bounds.v_min - margin, bounds.v_max + margin, false};
    l.scale = std::min(kMaxPlotW / (l.world.h_max - l.world.h_min), kMaxPlotH / (l.world.v_max - l.world.v_min));
    widen(l.world.h_min, l.world.h_max, kMinPlotW / l.scale);
    widen(l.world.v_min, l.world.v_max, kMinPlotH / l.scale);
    l.plot_w = (l.world.h_max - l.world.h_min) * l.scale;
    l.plot_h = (l.world.v_max - l.world.v_min) * l.scale;
    l.width = std::ceil(kLeft + std::max(l.plot_w, legend_w) + kRight);
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

std::string subtitle_of(const Toolpath& t, const SvgOptions& o) {
    const bool lathe = o.kind == dialects::MachineKind::lathe;
    std::string s = lathe ? (o.diameter_x ? "lathe, Z-X view, X drawn at the radius" : "lathe, Z-X view") : "mill, X-Y view";
    if (t.inch) s += ", inches (G20)";
    // Lengths in the drawing's unit (the interpreter measures mm).
    const auto length = [&](double mm) { return t.inch ? fmt::format("{:.2f} in", mm / 25.4) : fmt::format("{:.1f} mm", mm); };
    s += fmt::format(" | feed {} | rapid {}", length(t.feed_mm), length(t.rapid_mm));
    if (t.thread_mm > 0) s += fmt::format(" | thread {}", length(t.thread_mm));
    if (t.not_drawn > 0) s += fmt::format(" | the last {} moves are not drawn (the picture is full)", t.not_drawn);
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
    fmt::format_to(out, "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#999\"/>\n", num(kLeft),
                   num(kTop), num(l.plot_w), num(l.plot_h));
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

// Alarms last: a run stopped by an alarm ends where the alarm is, and the cross must stay visible.
void write_markers(Out out, const Toolpath& t, const Layout& l) {
    if (t.moves > 0) {
        start_marker(out, l.x(t.start.h), l.y(t.start.v));
        end_marker(out, l.x(t.end.h), l.y(t.end.v));
    }
    for (const Point& a : t.alarms) alarm_marker(out, l.x(a.h), l.y(a.v));
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

constexpr LegendItem kLegend[] = {
    {"rapid", [](Out o, double x, double y) { line_sample(o, kRapid, x, y); }},
    {"feed (lines, arcs)", [](Out o, double x, double y) { line_sample(o, kFeed, x, y); }},
    {"thread", [](Out o, double x, double y) { line_sample(o, kThread, x, y); }},
    {"start", [](Out o, double x, double y) { start_marker(o, x + 15, y); }},
    {"end", [](Out o, double x, double y) { end_marker(o, x + 15, y); }},
    {"alarm", [](Out o, double x, double y) { alarm_marker(o, x + 15, y); }},
};

double item_width(const LegendItem& item) { return 30 + 8 + kCharPx * std::char_traits<char>::length(item.label) + 18; }

// The alarm entry only when the picture has an alarm marker.
std::size_t legend_count(const Toolpath& t) { return t.alarms.empty() ? std::size(kLegend) - 1 : std::size(kLegend); }

double legend_width(const Toolpath& t) {
    double w = 0;
    for (std::size_t i = 0; i < legend_count(t); ++i) w += item_width(kLegend[i]);
    return w;
}

void write_legend(Out out, const Toolpath& t, const Layout& l) {
    const double y = l.bottom() + kTickArea + kRowH + 10;
    double x = kLeft;
    fmt::format_to(out, "<g class=\"legend\">\n");
    for (std::size_t i = 0; i < legend_count(t); ++i) {
        kLegend[i].sample(out, x, y);
        fmt::format_to(out, "<text x=\"{}\" y=\"{}\">{}</text>\n", num(x + 38), num(y + 4), kLegend[i].label);
        x += item_width(kLegend[i]);
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
    return render_svg(build_toolpath(events, {options.kind, options.diameter_x}), options);
}

std::string render_svg(const Toolpath& t, const SvgOptions& options) {
    if (t.bounds.empty) return no_motion_svg(options);
    const bool lathe = options.kind == dialects::MachineKind::lathe;
    const Layout l = make_layout(t.bounds, lathe, legend_width(t));
    std::string svg;
    svg.reserve(4096 + 64 * t.pieces.size());
    const Out out = std::back_inserter(svg);
    write_header(out, l.width, l.height, options.title, subtitle_of(t, options));
    write_grid(out, l, lathe && options.diameter_x ? 2.0 : 1.0);   // lathe X ticks read as programmed: diameters
    if (lathe) write_part_axis(out, l);
    write_axis_labels(out, l, options);
    write_paths(out, t, l);
    write_markers(out, t, l);
    write_scale_bar(out, l, t.inch);
    write_legend(out, t, l);
    svg += "</svg>\n";
    return svg;
}

}  // namespace kerf::plot
