// `kerf plot`: the toolpath of a dry run as an SVG picture. Pure: the interpreter's events in, the
// document out (the CLI writes it). Lathes are drawn in the Z–X view with the part axis, mills in
// the X–Y view (plot/toolpath.hpp); rapids dashed, feeds and arcs solid, threads in their own
// colour, with a grid, a scale bar, a legend and start/end markers.
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
};

// A complete SVG document ("<svg ...>...</svg>"). Without motion: a small picture saying so.
std::string render_svg(const std::vector<interpreter::Event>& events, const SvgOptions& options);
// The same for a toolpath built while the run went on (plot/toolpath.hpp ToolpathSink): the
// document's size is bounded by the toolpath's, whatever the length of the run.
std::string render_svg(const Toolpath& toolpath, const SvgOptions& options);

}  // namespace kerf::plot
