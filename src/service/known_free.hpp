// Where the poses a plan gains beyond its route (run_past_goal's point, lead_start_turn's arc)
// may go: only through cells on the map, free and known in the view, a stricter rule than the
// route's own (a passable unknown cell is not enough for a pose the planner did not search).
#pragma once

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"
#include "eaci/path/smoothing.hpp"

namespace eaci_service {

// On the map, free, and not unknown.
inline bool knownFree(const eaci::GridView& view, eaci::Cell c) {
  return view.isFree(c) && view.value(c) != view.interpretation().unknown_value;
}

// Every cell the straight segment between the centres of `from` and `to` passes or touches
// (eaci::traverseSegment) is knownFree; `from` == `to`: that cell is.
inline bool knownFreeAlong(const eaci::GridView& view, eaci::Cell from, eaci::Cell to) {
  bool clear = true;
  eaci::traverseSegment(from, to, [&](eaci::Cell c, double) { return clear = knownFree(view, c); });
  return clear;
}

}  // namespace eaci_service
