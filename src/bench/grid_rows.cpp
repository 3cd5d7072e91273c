#include "grid_rows.hpp"

#include <vector>

namespace eaci_bench {

nlohmann::json gridRows(const eaci::OccupancyMap& map) {
  const eaci::GridView view = map.view();
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < map.height; ++r) {
    std::vector<int> row(static_cast<std::size_t>(map.width));
    for (int c = 0; c < map.width; ++c) row[static_cast<std::size_t>(c)] = view.isObstacle(eaci::Cell{r, c}) ? 1 : 0;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace eaci_bench
