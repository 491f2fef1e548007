// LoadPlot: draws a load run over time as an SVG chart (`locator-load
// --plot FILE.svg`). Two panels share the time axis: above, the latency of
// successful calls per timeline slice (p50 and p99, in ms); below, the
// server's mean cost per query per slice. Each has axes, tick labels and a
// legend; a dashed vertical line marks where each phase after the first
// began (phase_signal.h).
//
// The document has exactly three polylines (p50, p99, cost), in that
// order; a series with no data is an empty polyline.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CLIENT_LOAD_LOAD_PLOT_H_
#define LOCATOR_CLIENT_LOAD_LOAD_PLOT_H_

#include <string>
#include <string_view>

#include "client/load/run_recorder.h"

namespace locator {

// The chart of `totals`' timeline and phases, titled `title`.
std::string RenderLoadPlot(std::string_view title, const RunTotals& totals);

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_LOAD_PLOT_H_
