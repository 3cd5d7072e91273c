// eaci::Cell in the tools' JSON: [row, col]. With this, nlohmann::json converts cells, routes
// (std::vector<Cell>) and structs holding them (NLOHMANN_DEFINE_TYPE_*) both ways.
#pragma once

#include <nlohmann/json.hpp>

#include "eaci/grid/cell.hpp"

namespace nlohmann {

template <>
struct adl_serializer<eaci::Cell> {
  template <class Json>
  static void to_json(Json& j, const eaci::Cell& c) {
    j = Json::array({c.row, c.col});
  }

  template <class Json>
  static void from_json(const Json& j, eaci::Cell& c) {
    c = eaci::Cell{j.at(0).template get<int>(), j.at(1).template get<int>()};
  }
};

}  // namespace nlohmann
