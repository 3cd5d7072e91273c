// Planning from where the robot stands. navfn and global_planner clear the robot's own cell
// before they plan (clearRobotCell): a robot inside the inflated band around an obstacle (a
// person stepped close, localisation jumped, the robot was put down by hand) still gets a plan.
// Here the way out is opened too, as cheaply as the band allows, so an 8-connected planner
// that never cuts corners can leave the band however deep the robot stands in it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "costmap_snapshot.hpp"
#include "plan_outcome.hpp"
#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"

namespace eaci_service {

struct StartCellCheck {
  bool ok = false;
  // When !ok: kStartOffMap or kStartBlocked (lethal, or no way out of the band); kOk with
  // `stopped` when should_stop ended the search first (the caller knows which stop).
  PlanOutcome outcome = PlanOutcome::kOk;
  bool stopped = false;
  std::string error;       // when !ok: why no plan can start here
  int cells_opened = 0;    // cells of the band to make passable (0: the start cell was free)
  std::vector<eaci::Cell> opened;  // those cells (row 0 = top), from the free cell back to the start
  std::uint8_t opened_cost = 0;    // the cost they take: lethal_cost - 1
  std::uint8_t start_cost = 0;     // the start cell's cost before
};

// Checks the start cell of `costmap` as `interpretation` reads it (lethal_cost, allow_unknown).
// A free start cell is left alone. A start cell that is an obstacle to the planner but not a
// lethal one (costmap_2d's 254) -- the inscribed band, a cost from lethal_cost up to 253, or an
// unknown cell when unknown cells are obstacles -- is opened together with the cheapest
// 4-connected run of such cells to the nearest free cell (Dijkstra on the cells' costs): those
// cells are to get cost lethal_cost - 1, the costliest passable cost (`opened`, `opened_cost`:
// the caller opens them in its copy), so the route leaves the band at once and by the shortest way. A start in a lethal cell, or one whose band meets no free
// cell (walled in by lethal cells), is refused with the reason. `should_stop` is asked every
// few thousand cells (a band as large as the map is searched no longer than the plan's time).
StartCellCheck openStartCell(const CostmapSnapshot& costmap, const eaci::CellInterpretation& interpretation,
                             eaci::Cell start, const std::function<bool()>& should_stop = {});

}  // namespace eaci_service
