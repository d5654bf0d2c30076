// plot/svg: strokes, arcs (SVG `A` with the sweep flag derived by hand for G02/G03 on a lathe and a
// mill), full circles, projections, lathe X at the radius, bounds, scale bar, legend, empty traces.
#include <catch2/catch.hpp>

#include <cmath>

#include "plot/svg.hpp"
#include "tests/plot/svg_reader.hpp"

using namespace kerf;
using interpreter::Event;
using interpreter::EventKind;
using interpreter::Position;
using test::attribute;
using test::elements_with;
using test::number_attribute;
using test::path_commands;
using test::PathCommand;

namespace {

Position xyz(double x, double y, double z) { return {x, y, z, 0, 0, 0}; }

Event move(EventKind kind, Position start, Position end) {
    Event e;
    e.kind = kind;
    e.start = start;
    e.end = end;
    return e;
}

// An arc event as the interpreter emits it: the centre with the start's normal coordinate.
Event arc(EventKind kind, Position start, Position end, Position center) {
    Event e = move(kind, start, end);
    e.center = center;
    return e;
}

const plot::SvgOptions kLathe{dialects::MachineKind::lathe, true, "lathe", plot::Frame::part};
const plot::SvgOptions kMill{dialects::MachineKind::mill, false, "mill", plot::Frame::part};
const plot::SvgOptions kMillAll{dialects::MachineKind::mill, false, "mill", plot::Frame::all};   // --frame all

// The commands of the one path with this class.
std::vector<PathCommand> path_of(const std::string& svg, const std::string& cls) {
    const auto paths = elements_with(svg, "<path class=\"" + cls + "\"");
    REQUIRE(paths.size() == 1);
    return path_commands(attribute(paths[0], "d"));
}

std::vector<PathCommand> commands(const std::vector<PathCommand>& all, char letter) {
    std::vector<PathCommand> out;
    for (const PathCommand& c : all)
        if (c.letter == letter) out.push_back(c);
    return out;
}

// The end point of a command (the last two arguments).
std::pair<double, double> end_of(const PathCommand& c) {
    REQUIRE(c.args.size() >= 2);
    return {c.args[c.args.size() - 2], c.args.back()};
}

}  // namespace

TEST_CASE("plot: a rapid is a dashed path, a feed a solid one, a thread a solid one of its own colour") {
    const std::vector<Event> events{move(EventKind::rapid, xyz(0, 0, 0), xyz(10, 0, 0)),
                                    move(EventKind::linear, xyz(10, 0, 0), xyz(10, 10, 0)),
                                    move(EventKind::thread, xyz(10, 10, 0), xyz(0, 10, 0))};
    const std::string svg = plot::render_svg(events, kMill);
    const auto rapid = elements_with(svg, "<path class=\"rapid\"");
    const auto feed = elements_with(svg, "<path class=\"feed\"");
    const auto thread = elements_with(svg, "<path class=\"thread\"");
    REQUIRE(rapid.size() == 1);
    REQUIRE(feed.size() == 1);
    REQUIRE(thread.size() == 1);
    CHECK(!attribute(rapid[0], "stroke-dasharray").empty());
    CHECK(attribute(feed[0], "stroke-dasharray").empty());
    CHECK(attribute(thread[0], "stroke-dasharray").empty());
    CHECK(attribute(rapid[0], "stroke") != attribute(feed[0], "stroke"));
    CHECK(attribute(thread[0], "stroke") != attribute(feed[0], "stroke"));
    CHECK(attribute(thread[0], "stroke") != attribute(rapid[0], "stroke"));
    // Each path starts where the previous one ended (the runs are cut by stroke, not by position).
    const auto r = path_commands(attribute(rapid[0], "d"));
    const auto f = path_commands(attribute(feed[0], "d"));
    REQUIRE(r.size() == 2);
    REQUIRE(f.size() == 2);
    CHECK(f[0].args == r[1].args);
    // Mill view: X to the right, Y up (SVG y down).
    CHECK(r[1].args[0] > r[0].args[0]);
    CHECK(r[1].args[1] == r[0].args[1]);
    CHECK(f[1].args[1] < f[0].args[1]);
}

TEST_CASE("plot: consecutive feed moves share one path; a jump starts a new subpath") {
    const std::vector<Event> events{move(EventKind::linear, xyz(0, 0, 0), xyz(10, 0, 0)),
                                    move(EventKind::linear, xyz(10, 0, 0), xyz(10, 5, 0)),
                                    move(EventKind::linear, xyz(20, 5, 0), xyz(20, 0, 0))};   // after a shift
    const auto d = path_of(plot::render_svg(events, kMill), "feed");
    REQUIRE(d.size() == 5);
    CHECK(std::string{d[0].letter, d[1].letter, d[2].letter, d[3].letter, d[4].letter} == "MLLML");
}

// O0004 N60/N70 (reference/semantics.md §3): from X30 Z-22 `G2 X40 Z-27 R5`, centre X40 Z-22. In the
// Z-right X-up view the start (Z-22, r15) is straight below the centre (Z-22, r20) and the end
// (Z-27, r20) straight left of it: from the bottom to the left is a quarter turn clockwise as seen,
// which is SVG's positive-angle direction (y down): sweep flag 1. Run backwards with G3 it is
// counter-clockwise: flag 0. A quarter circle's chord is r·√2 — with X drawn as the diameter the
// ends would be √125 apart, not 5·√2.
TEST_CASE("plot: lathe G02 and G03 arcs are SVG arcs with sweep flags 1 and 0, X at the radius") {
    const Position start = xyz(30, 0, -22), end = xyz(40, 0, -27), centre = xyz(40, 0, -22);
    for (const bool g02 : {true, false}) {
        INFO((g02 ? "G02" : "G03"));
        const Event e = g02 ? arc(EventKind::arc_cw, start, end, centre) : arc(EventKind::arc_ccw, end, start, centre);
        const auto d = path_of(plot::render_svg({e}, kLathe), "feed");
        REQUIRE(d.size() == 2);
        REQUIRE(d[1].letter == 'A');
        REQUIRE(d[1].args.size() == 7);
        CHECK(d[1].args[0] == d[1].args[1]);   // a circle
        CHECK(d[1].args[3] == 0);              // large-arc: 90°
        CHECK(d[1].args[4] == (g02 ? 1 : 0));  // sweep
        const double chord = std::hypot(d[1].args[5] - d[0].args[0], d[1].args[6] - d[0].args[1]);
        CHECK(chord == Approx(d[1].args[0] * std::sqrt(2.0)).epsilon(1e-3));
        // The move goes left (−Z) and up (+X) for G02.
        const double dx = d[1].args[5] - d[0].args[0], dy = d[1].args[6] - d[0].args[1];
        CHECK((g02 ? dx < 0 && dy < 0 : dx > 0 && dy > 0));
    }
}

// Mill, seen from +Z with X right and Y up: from (10, 0) about the origin, G02 to (0, −10) turns a
// quarter clockwise as seen (flag 1), G03 to (0, 10) a quarter counter-clockwise (flag 0).
TEST_CASE("plot: mill G02 and G03 arcs are SVG arcs with sweep flags 1 and 0") {
    const auto cw = path_of(plot::render_svg({arc(EventKind::arc_cw, xyz(10, 0, 0), xyz(0, -10, 0), xyz(0, 0, 0))}, kMill),
                            "feed");
    const auto ccw = path_of(plot::render_svg({arc(EventKind::arc_ccw, xyz(10, 0, 0), xyz(0, 10, 0), xyz(0, 0, 0))}, kMill),
                             "feed");
    REQUIRE(cw.size() == 2);
    REQUIRE(ccw.size() == 2);
    REQUIRE(cw[1].letter == 'A');
    REQUIRE(ccw[1].letter == 'A');
    CHECK(cw[1].args[4] == 1);
    CHECK(ccw[1].args[4] == 0);
    CHECK(cw[1].args[6] > cw[0].args[1]);    // ends lower on the screen (−Y)
    CHECK(ccw[1].args[6] < ccw[0].args[1]);  // ends higher (+Y)
}

// G02 from (10, 0) to (0, 10) about the origin is 270° (0° → −90° → −180° → −270°). Drawn as two
// halves through the point at −135° (lower left of the centre); the centre's pixel is (x of the
// end, y of the start).
TEST_CASE("plot: an arc over 180 degrees is two SVG arcs through its middle") {
    const auto d = path_of(plot::render_svg({arc(EventKind::arc_cw, xyz(10, 0, 0), xyz(0, 10, 0), xyz(0, 0, 0))}, kMill),
                           "feed");
    REQUIRE(d.size() == 3);
    REQUIRE(d[1].letter == 'A');
    REQUIRE(d[2].letter == 'A');
    const double cx = d[2].args[5], cy = d[0].args[1], r = d[1].args[0];
    const auto [mx, my] = end_of(d[1]);
    CHECK(mx == Approx(cx - r / std::sqrt(2.0)).epsilon(1e-3));
    CHECK(my == Approx(cy + r / std::sqrt(2.0)).epsilon(1e-3));
    CHECK(d[1].args[3] == 0);
    CHECK(d[1].args[4] == 1);
    CHECK(d[2].args[4] == 1);
}

TEST_CASE("plot: a full circle is two half arcs back to the start") {
    // G03 I-10 from (10, 0): centre (0, 0), end = start.
    const auto d = path_of(plot::render_svg({arc(EventKind::arc_ccw, xyz(10, 0, 0), xyz(10, 0, 0), xyz(0, 0, 0))}, kMill),
                           "feed");
    REQUIRE(d.size() == 3);
    REQUIRE(d[1].letter == 'A');
    REQUIRE(d[2].letter == 'A');
    const auto [mx, my] = end_of(d[1]);
    CHECK(my == Approx(d[0].args[1]));                           // the opposite point (−10, 0)
    CHECK(d[0].args[0] - mx == Approx(2 * d[1].args[0]).epsilon(1e-3));   // a diameter away
    CHECK(end_of(d[2]) == std::make_pair(d[0].args[0], d[0].args[1]));
    CHECK(d[1].args[4] == 0);
    CHECK(d[2].args[4] == 0);
}

TEST_CASE("plot: a helix about the view normal draws its circle; an arc in another plane is projected") {
    // G17 G03 with Z moving: the X-Y picture is the quarter circle.
    const auto helix = path_of(
        plot::render_svg({arc(EventKind::arc_ccw, xyz(10, 0, 0), xyz(0, 10, -5), xyz(0, 0, 0))}, kMill), "feed");
    REQUIRE(helix.size() == 2);
    CHECK(helix[1].letter == 'A');
    // G18 G02 from X10 Z0 to X0 Z10 about the origin (frame (Z, X): from 90° to 0°, a quarter
    // clockwise). Seen from +Z it runs along X at Y0: its projected points lie on one horizontal
    // line, so the simplification (plot/toolpath.hpp) draws it as one line from X10 to X0.
    const auto g18 = path_of(
        plot::render_svg({arc(EventKind::arc_cw, xyz(10, 0, 0), xyz(0, 0, 10), xyz(0, 0, 0))}, kMill), "feed");
    REQUIRE(g18.size() == 2);
    CHECK(commands(g18, 'A').empty());
    CHECK(g18[1].letter == 'L');
    const double x0 = g18.front().args[0], x1 = end_of(g18.back()).first;
    CHECK(x1 < x0);
    CHECK(g18[1].args[1] == Approx(g18.front().args[1]));
}

// X0 Z0 → X30 Z0 (rapid, 15 mm of radius upwards) then Z0 → Z-15 at X30 (15 mm to the left): on
// the picture both are equally long, and the part axis runs through the start.
TEST_CASE("plot: lathe X is drawn at the radius, Z to the right, with the part axis at X0") {
    const std::vector<Event> events{move(EventKind::rapid, xyz(0, 0, 0), xyz(30, 0, 0)),
                                    move(EventKind::linear, xyz(30, 0, 0), xyz(30, 0, -15))};
    const std::string svg = plot::render_svg(events, kLathe);
    const auto r = path_of(svg, "rapid");
    const auto f = path_of(svg, "feed");
    const double up = r[0].args[1] - r[1].args[1];
    const double left = f[0].args[0] - f[1].args[0];
    CHECK(up > 0);
    CHECK(left > 0);
    CHECK(up == Approx(left).epsilon(1e-4));
    CHECK(r[0].args[0] == r[1].args[0]);
    const auto axis = elements_with(svg, "class=\"part-axis\"");
    REQUIRE(axis.size() == 1);
    CHECK(number_attribute(axis[0], "y1") == Approx(r[0].args[1]));
    CHECK(!attribute(axis[0], "stroke-dasharray").empty());
    // Tick labels read as programmed: the X30 line is labelled with diameters.
    CHECK(svg.find("values are diameters") != std::string::npos);
    CHECK(elements_with(plot::render_svg(events, kMill), "class=\"part-axis\"").empty());
}

// A G03 semicircle from (10, 0) to (−10, 0) about the origin reaches (0, 10), above both ends; the
// plot area must hold it, and with --frame all every point of every path and marker lies inside the
// picture (framing the part, the rapid's start is outside: the next test case).
TEST_CASE("plot: the view holds every point, arc extremes included") {
    const std::vector<Event> events{move(EventKind::rapid, xyz(-50, -20, 5), xyz(10, 0, 0)),
                                    arc(EventKind::arc_ccw, xyz(10, 0, 0), xyz(-10, 0, 0), xyz(0, 0, 0))};
    // Framing the part: the arc alone, its apex Y10 included: -10..10 x 0..10 with 2 (10 %) around.
    CHECK(attribute(elements_with(plot::render_svg(events, kMill), "class=\"frame\"")[0], "data-view") == "-12 -2 12 12");
    const std::string svg = plot::render_svg(events, kMillAll);
    const auto root = elements_with(svg, "<svg ");
    REQUIRE(root.size() == 1);
    CHECK(attribute(root[0], "viewBox") == "0 0 " + attribute(root[0], "width") + " " + attribute(root[0], "height"));
    const auto frame = elements_with(svg, "<rect x=");
    REQUIRE(!frame.empty());   // the plot frame is the first positioned rect
    const double left = number_attribute(frame[0], "x"), top = number_attribute(frame[0], "y");
    const double right = left + number_attribute(frame[0], "width");
    const double bottom = top + number_attribute(frame[0], "height");
    for (const char* cls : {"rapid", "feed"}) {
        for (const PathCommand& c : path_of(svg, cls)) {
            const auto [x, y] = end_of(c);
            CHECK(x > left);
            CHECK(x < right);
            CHECK(y > top);
            CHECK(y < bottom);
        }
    }
    const auto d = path_of(svg, "feed");
    const double r = d[1].args[0];
    const double apex_y = d[0].args[1] - r;   // the centre is on the chord (a semicircle)
    CHECK(apex_y > top);
    const auto start = elements_with(svg, "<circle class=\"start\"");
    REQUIRE(start.size() == 2);   // the marker and its legend sample
    CHECK(number_attribute(start[0], "cx") > left);
    CHECK(number_attribute(start[0], "cy") < bottom);
}

// A 100 mm feed along X gives the pixels per mm; the scale bar's length is its label times that,
// and the label is a 1-2-5 number.
TEST_CASE("plot: scale bar of a round length, legend of what the picture shows") {
    const std::vector<Event> events{move(EventKind::linear, xyz(0, 0, 0), xyz(100, 0, 0))};
    const std::string svg = plot::render_svg(events, kMill);
    const auto f = path_of(svg, "feed");
    const double px_per_mm = (f[1].args[0] - f[0].args[0]) / 100;
    const std::size_t at = svg.find("<g class=\"scale\">");
    REQUIRE(at != std::string::npos);
    const std::string scale = svg.substr(at, svg.find("</g>", at) - at);
    const std::size_t h = scale.find(" h");
    REQUIRE(h != std::string::npos);
    const double bar_px = std::strtod(scale.c_str() + h + 2, nullptr);
    const std::size_t label = scale.find("\">", scale.find("<text")) + 2;
    const double mm = std::strtod(scale.c_str() + label, nullptr);
    CHECK(scale.find(" mm</text>") != std::string::npos);
    CHECK(bar_px / px_per_mm == Approx(mm).epsilon(1e-3));
    const double mantissa = mm / std::pow(10.0, std::floor(std::log10(mm)));
    CHECK((mantissa == Approx(1) || mantissa == Approx(2) || mantissa == Approx(5)));
    const std::size_t legend = svg.find("<g class=\"legend\">");
    REQUIRE(legend != std::string::npos);
    // One feed line: the legend says feed, start and end, nothing it does not show.
    for (const char* text : {">feed<", ">start<", ">end<"}) CHECK(svg.find(text, legend) != std::string::npos);
    for (const char* text : {">rapid<", ">feed (lines, arcs)<", ">thread<", ">alarm<", ">rapid leaving the frame<"})
        CHECK(svg.find(text) == std::string::npos);
    CHECK(svg.find(">mill</text>") != std::string::npos);   // the title
    CHECK(svg.find("X \u2192") != std::string::npos);
    CHECK(svg.find("\u2191 Y") != std::string::npos);
}

TEST_CASE("plot: start and end markers sit on the first and last points; alarms are marked") {
    Event alarm;
    alarm.kind = EventKind::alarm;
    alarm.end = xyz(5, 5, 0);
    const std::vector<Event> events{move(EventKind::rapid, xyz(0, 0, 0), xyz(10, 0, 0)),
                                    move(EventKind::linear, xyz(10, 0, 0), xyz(10, 10, 0)), alarm};
    const std::string svg = plot::render_svg(events, kMillAll);   // the start X0 Y0 is outside the part's frame
    const auto r = path_of(svg, "rapid");
    const auto f = path_of(svg, "feed");
    const auto start = elements_with(svg, "<circle class=\"start\"");
    const auto end = elements_with(svg, "<rect class=\"end\"");
    REQUIRE(!start.empty());
    REQUIRE(!end.empty());
    CHECK(number_attribute(start[0], "cx") == Approx(r[0].args[0]));
    CHECK(number_attribute(start[0], "cy") == Approx(r[0].args[1]));
    CHECK(number_attribute(end[0], "x") + number_attribute(end[0], "width") / 2 == Approx(f[1].args[0]));
    CHECK(number_attribute(end[0], "y") + number_attribute(end[0], "height") / 2 == Approx(f[1].args[1]));
    CHECK(elements_with(svg, "<path class=\"alarm\"").size() == 2);   // the marker and the legend sample
    CHECK(svg.find(">alarm<") != std::string::npos);
}

TEST_CASE("plot: no motion gives a small valid picture that says so") {
    Event tool;
    tool.kind = EventKind::tool_change;
    for (const std::vector<Event>& events : {std::vector<Event>{}, std::vector<Event>{tool}}) {
        const std::string svg = plot::render_svg(events, kLathe);
        CHECK(svg.rfind("<svg", 0) == 0);
        CHECK(svg.find("no motion") != std::string::npos);
        CHECK(svg.find("<path") == std::string::npos);
        CHECK(svg.substr(svg.size() - 7) == "</svg>\n");
        CHECK(test::tags_balanced(svg));
    }
}

TEST_CASE("plot: the title is escaped, numbers are compact, the document is balanced") {
    const std::vector<Event> events{move(EventKind::linear, xyz(0, 0, 0), xyz(1.5, 0.25, 0))};
    plot::SvgOptions options = kMill;
    options.title = "a<b & \"c\"";
    const std::string svg = plot::render_svg(events, options);
    CHECK(svg.find(">a&lt;b &amp; &quot;c&quot;</text>") != std::string::npos);
    CHECK(test::tags_balanced(svg));
    CHECK(svg.find(".000") == std::string::npos);
    CHECK(svg.find("-0 ") == std::string::npos);
    CHECK(svg.find("nan") == std::string::npos);
}

// Positions are as programmed and lengths in mm (docs/trace.md): a G20 program's events say
// `inch`, its 1-inch line has length_mm 25.4, and the picture, scale bar and lengths are in inches.
TEST_CASE("plot: an inch program gets an inch scale bar") {
    Event e = move(EventKind::linear, xyz(0, 0, 0), xyz(1, 0, 0));
    e.length_mm = 25.4;
    e.inch = true;
    const std::string inch = plot::render_svg({e}, kMill);
    CHECK(inch.find(" in</text>") != std::string::npos);
    CHECK(inch.find("inches (G20)") != std::string::npos);
    CHECK(inch.find("feed 1.00 in") != std::string::npos);
    e.length_mm = 1;
    e.inch = false;
    const std::string mm = plot::render_svg({e}, kMill);
    CHECK(mm.find(" mm</text>") != std::string::npos);
    CHECK(mm.find("feed 1.0 mm") != std::string::npos);
}

// The legend's entries follow the strokes drawn (the issue: "thread" was listed for every program).
TEST_CASE("plot: the legend lists rapid, feed, arcs and thread only when the picture has them") {
    const auto legend_of = [](const std::vector<Event>& events) {
        const std::string svg = plot::render_svg(events, kMill);
        const std::size_t at = svg.find("<g class=\"legend\">");
        REQUIRE(at != std::string::npos);
        return svg.substr(at);
    };
    const std::string lines = legend_of({move(EventKind::rapid, xyz(0, 0, 0), xyz(10, 0, 0)),
                                         move(EventKind::linear, xyz(10, 0, 0), xyz(10, 10, 0))});
    CHECK(lines.find(">rapid<") != std::string::npos);
    CHECK(lines.find(">feed<") != std::string::npos);
    CHECK(lines.find(">thread<") == std::string::npos);
    const std::string arcs = legend_of({arc(EventKind::arc_ccw, xyz(10, 0, 0), xyz(0, 10, 0), xyz(0, 0, 0))});
    CHECK(arcs.find(">feed (lines, arcs)<") != std::string::npos);
    CHECK(arcs.find(">rapid<") == std::string::npos);
    const std::string thread = legend_of({move(EventKind::linear, xyz(0, 0, 0), xyz(10, 0, 0)),
                                          move(EventKind::thread, xyz(10, 0, 0), xyz(10, 10, 0))});
    CHECK(thread.find(">thread<") != std::string::npos);
}

// A mill path: a rapid from X200 Y150 (far from the part) to X0 Y0, a 10 x 10 square of feed moves,
// a rapid back to X200 Y150. Framing the part (default) by hand: the cuts span 0..10 on both axes,
// 10 % margin = 1 on every side: -1..11; the scale min(900 / 12, 640 / 12) = 53.333 px/mm makes the
// plot 640 x 640 px. The rapid back leaves the frame at X11: t = 1 / 190 along it from X10 Y10
// (direction (190, 140)), Y = 10 + 140 / 190 = 10.737, i.e. x = 76 + 12 x 53.333 = 716 px,
// y = 70 + (11 - 10.737) x 53.333 = 84.035 px. Framing all: X0..200, Y0..150, 5 % of 200 = 10:
// -10..210, -10..160.
TEST_CASE("plot: the picture frames the cutting moves; rapids leaving it are clipped with an arrow") {
    const std::vector<Event> events{move(EventKind::rapid, xyz(200, 150, 0), xyz(0, 0, 0)),
                                    move(EventKind::linear, xyz(0, 0, 0), xyz(10, 0, 0)),
                                    move(EventKind::linear, xyz(10, 0, 0), xyz(10, 10, 0)),
                                    move(EventKind::linear, xyz(10, 10, 0), xyz(0, 10, 0)),
                                    move(EventKind::linear, xyz(0, 10, 0), xyz(0, 0, 0)),
                                    move(EventKind::rapid, xyz(0, 0, 0), xyz(10, 10, 0)),
                                    move(EventKind::rapid, xyz(10, 10, 0), xyz(200, 150, 0))};
    const std::string svg = plot::render_svg(events, kMill);
    const auto frame = elements_with(svg, "class=\"frame\"");
    REQUIRE(frame.size() == 1);
    CHECK(attribute(frame[0], "data-view") == "-1 -1 11 11");
    CHECK(attribute(frame[0], "width") == "640");
    CHECK(attribute(frame[0], "height") == "640");
    const auto arrows = elements_with(svg, "<path class=\"leaves\"");
    REQUIRE(arrows.size() == 2);   // the rapid back, and the legend's sample
    const auto tip = path_commands(attribute(arrows[0], "d"));
    REQUIRE(!tip.empty());
    CHECK(tip[0].args[0] == Approx(716));
    CHECK(tip[0].args[1] == Approx(84.035).margin(1e-3));
    CHECK(svg.find("<title>rapid to X200 Y150</title>") != std::string::npos);
    CHECK(svg.find("<g clip-path=\"url(#plot-area)\">") != std::string::npos);
    // The start (X200 Y150) and the end (the same) are outside: neither marker nor legend entry.
    CHECK(svg.find("class=\"start\"") == std::string::npos);
    CHECK(svg.find("class=\"end\"") == std::string::npos);

    plot::SvgOptions all = kMill;
    all.frame = plot::Frame::all;
    const std::string whole = plot::render_svg(events, all);
    const auto whole_frame = elements_with(whole, "class=\"frame\"");
    REQUIRE(whole_frame.size() == 1);
    CHECK(attribute(whole_frame[0], "data-view") == "-10 -10 210 160");
    CHECK(whole.find("clip-path") == std::string::npos);
    CHECK(whole.find("class=\"leaves\"") == std::string::npos);
    CHECK(elements_with(whole, "<circle class=\"start\"").size() == 2);   // the marker and its legend sample

    // Without a cutting move the picture frames the whole path.
    const std::string rapids = plot::render_svg({events.front()}, kMill);
    CHECK(attribute(elements_with(rapids, "class=\"frame\"")[0], "data-view") == "-10 -10 210 160");
}
