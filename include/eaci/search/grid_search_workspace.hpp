// The grid search (searchGrid) into buffers that stay for the next one, for callers that
// search often and read few cells, such as A*: allocated once per map size, and a search
// costs only the cells it labels (KeptLabels: no clearing of whole-map arrays).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "eaci/grid/cell_window.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/search/bucket_queue.hpp"
#include "eaci/search/grid_search.hpp"
#include "eaci/search/route_back.hpp"
#include "eaci/search/search_labels.hpp"
#include "eaci/search/search_request.hpp"

namespace eaci {

// The moves are always kept (keep_moves is implied). Read the answers before the next search.
class GridSearchWorkspace {
 public:
  void search(const CostGrid& grid, const GridSearchRequest& request) {
    window_ = request.window.value_or(CellWindow::whole(grid));
    labels_.prepare(window_.size());
    detail::StampedLabels<> labels = labels_.of(0);
    detail::runGridSearch(grid, request, window_, labels, open_, frontier_, stopped_);
  }

  // The last search was ended by its stop check: its labels are partial.
  bool stopped() const { return stopped_; }
  const CellWindow& window() const { return window_; }
  // Route cost from the source; +infinity = not reached (or outside the window).
  double at(Cell c) const {
    if (!window_.contains(c)) return std::numeric_limits<double>::infinity();
    return labels_.of(0).cost(static_cast<std::uint32_t>(window_.slot(c)));
  }
  bool reached(Cell c) const { return std::isfinite(at(c)); }
  // The cells from the source to `c` of a search by cost; empty when `c` was not reached.
  CellPath routeTo(Cell c) const {
    CellPath route;
    if (!reached(c)) return route;
    const detail::StampedLabels<> labels = labels_.of(0);
    appendRouteBack(window_, c, [&labels](std::size_t slot) { return labels.moveInto(slot); }, route);
    std::reverse(route.begin(), route.end());
    return route;
  }

 private:
  detail::KeptLabels<1> labels_;
  bool stopped_ = false;
  CellWindow window_;
  alignas(64) detail::OrderedBucketQueue open_;
  std::vector<std::uint32_t> frontier_;
};

}  // namespace eaci
