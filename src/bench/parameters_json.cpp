#include "parameters_json.hpp"

#include <variant>

namespace eaci_bench {

nlohmann::json toJson(const eaci::Parameters& p) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, value] : eaci::parameterValues(p))
    std::visit([&out, &name = name](const auto& v) { out[name] = v; }, value);
  return out;
}

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
