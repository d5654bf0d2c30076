// `kerf plot`: the toolpath of a dry run as an SVG picture. Pure: the interpreter's events in, the
// document out (the CLI writes it). Lathes are drawn in the Z–X view with the part axis, mills in
// the X–Y view (plot/toolpath.hpp); rapids dashed, feeds and arcs solid, threads in their own
// colour, with a grid, a scale bar, a legend of what the drawing shows and start/end markers. The
// plot area frames the part (SvgOptions::frame); the frame rect carries the region it shows as
// `data-view="h_min v_min h_max v_max"` in the drawing's unit (lathe: Z and the X radius).
#pragma once

#include <string>
#include <vector>

#include "dialects/dialect.hpp"
#include "interpreter/events.hpp"
#include "plot/toolpath.hpp"

namespace kerf::plot {

struct SvgOptions {
    dialects::MachineKind kind = dialects::MachineKind::mill;
    bool diameter_x = false;   // lathe: event X is a diameter (Setup::diameter_x); drawn at the radius
    std::string title;         // shown on top (escaped here)
    // Frame::part (the default): the plot area shows the cutting moves with a margin; rapids that
    // leave it are clipped at its edge with an arrow (its tooltip names where they go), and markers
    // outside it are not drawn. Frame::all: the whole path.
    Frame frame = Frame::part;
};

// A complete SVG document ("<svg ...>...</svg>"). Without motion: a small picture saying so.
std::string render_svg(const std::vector<interpreter::Event>& events, const SvgOptions& options);
// The same for a toolpath built while the run went on (plot/toolpath.hpp ToolpathSink): the
// document's size is bounded by the toolpath's, whatever the length of the run.
std::string render_svg(const Toolpath& toolpath, const SvgOptions& options);

}  // namespace kerf::plot
