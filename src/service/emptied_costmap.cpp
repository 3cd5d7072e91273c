#include "emptied_costmap.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>


namespace eaci_service {

bool isUniform(const CostmapView& costmap) {
  const std::size_t cells = costmap.cellCount();
  if (cells == 0 || costmap.cells == nullptr) return false;
  // Each cell equal to the next: one pass, ended by the first difference.
  return std::memcmp(costmap.cells, costmap.cells + 1, cells - 1) == 0;
}

std::optional<CostmapSnapshot> placedInto(const CostmapSnapshot& last, const eaci::MapFrame& frame, std::uint8_t fill) {
  const double resolution = frame.resolution;
  if (!(resolution > 0) || last.frame.resolution != resolution) return std::nullopt;
  // Where `last`'s bottom-left cell lies in `frame`, in cells; origins a fraction of a cell
  // apart put no old cell on a new one.
  const Eigen::Vector2d shift = (last.frame.origin - frame.origin) / resolution;
  const Eigen::Vector2d whole = shift.array().round();
  if (!whole.allFinite() || (shift - whole).cwiseAbs().maxCoeff() > 1e-3) return std::nullopt;
  const long long dx = static_cast<long long>(whole.x()), dy = static_cast<long long>(whole.y());

  CostmapSnapshot placed;
  placed.frame = frame;
  placed.frame_id = last.frame_id;
  placed.order = eaci::RowOrder::kBottomFirst;
  placed.cells.assign(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), fill);
  // Columns of `last` that land on `frame`: [c0, c1), at dx + c in the new frame.
  const long long c0 = std::max(0LL, -dx), c1 = std::min<long long>(last.frame.width, frame.width - dx);
  if (c0 >= c1) return placed;
  for (long long from_bottom = 0; from_bottom < last.frame.height; ++from_bottom) {
    const long long to_bottom = from_bottom + dy;
    if (to_bottom < 0 || to_bottom >= frame.height) continue;
    // Rows counted from the bottom in both: the buffer row of `last` depends on its order.
    const long long last_row = last.order == eaci::RowOrder::kBottomFirst ? from_bottom : last.frame.height - 1 - from_bottom;
    const std::uint8_t* from = last.cells.data() + last_row * last.frame.width + c0;
    std::uint8_t* to = placed.cells.data() + to_bottom * frame.width + (dx + c0);
    std::copy(from, from + (c1 - c0), to);
  }
  return placed;
}

std::optional<CostmapSnapshot> EmptiedCostmapStandIn::standIn(const CostmapView& costmap,
                                                              const CostmapSnapshot* last_filled,
                                                              Clock::time_point last_filled_read, Clock::time_point now,
                                                              std::string& said) {
  filled_ = !isUniform(costmap);
  if (filled_ || last_filled == nullptr) return std::nullopt;
  const eaci::MapFrame& a = costmap.frame;
  const eaci::MapFrame& b = last_filled->frame;
  const bool resized = a.width != b.width || a.height != b.height || a.resolution != b.resolution || a.origin != b.origin;
  if (!resized || now - last_filled_read > max_age_) return std::nullopt;
  const std::uint8_t value = costmap.cells[0];
  std::optional<CostmapSnapshot> placed = placedInto(*last_filled, costmap.frame, value);
  if (!placed) return std::nullopt;
  placed->frame_id = costmap.frame_id;
  said = "the costmap (" + std::to_string(costmap.frame.width) + " x " + std::to_string(costmap.frame.height) +
         " cells) was resized and holds " + std::to_string(value) + " in every cell: costmap_2d has emptied it and "
         "not filled it yet; planning on the last filled costmap, read " +
         std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(now - last_filled_read).count()) +
         " ms ago, placed into its frame";
  return placed;
}

}  // namespace eaci_service
