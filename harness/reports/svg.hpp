// Plots as SVG, written directly (no plotting dependency): the series of one figure drawn
// together, linear or logarithmic axes, a legend, and for a series with a reference slope a
// dashed line of that slope (log-log) through the series' first point, e.g. the claimed order of
// an integrator beside its measured errors.
#pragma once

#include "properties/support/figures.hpp"

#include <string>
#include <vector>

namespace gm::harness {

// Points that cannot be drawn (non-finite, or <= 0 on a logarithmic axis) are left out and
// counted in a note under the plot. An empty figure still yields a valid SVG saying so.
std::string svg_plot(const std::string& title, const std::vector<Series>& series);

std::string xml_escape(const std::string& s);

}  // namespace gm::harness
