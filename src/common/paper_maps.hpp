// The paper's benchmark maps as maps/paper/paper_maps.json lists them (the one source of their
// start and goal cells, optima and the paper's table rows), for eaci_bench and the tests.
#pragma once

#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eaci/grid/cell.hpp"

namespace eaci::paper {

struct PaperMap {
  std::string name;    // the file is name + ".txt"
  std::string table;   // "Table 1", ...; "" for a map the paper does not report
  Cell start, goal;
  double optimum_corner_cutting = 0.0;
  double optimum_no_corner_cutting = std::numeric_limits<double>::infinity();  // +inf: no path
  bool has_paper_rows = false;  // the paper's ACO and EACI rows exist for this map

  std::string file() const { return name + ".txt"; }
};

// Reads `maps_dir`/paper_maps.json; throws std::runtime_error naming the file when it is missing or malformed.
inline std::vector<PaperMap> loadPaperMaps(const std::string& maps_dir) {
  const std::string path = maps_dir + "/paper_maps.json";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<PaperMap> maps;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const nlohmann::json& m : j.at("maps")) {
      PaperMap p;
      p.name = m.at("name").get<std::string>();
      p.table = m.at("table").get<std::string>();
      p.start = Cell{m.at("start").at(0).get<int>(), m.at("start").at(1).get<int>()};
      p.goal = Cell{m.at("goal").at(0).get<int>(), m.at("goal").at(1).get<int>()};
      p.optimum_corner_cutting = m.at("optimum_corner_cutting").get<double>();
      if (!m.at("optimum_no_corner_cutting").is_null())
        p.optimum_no_corner_cutting = m.at("optimum_no_corner_cutting").get<double>();
      p.has_paper_rows = !m.at("paper_aco").is_null();
      maps.push_back(p);
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return maps;
}

inline PaperMap paperMapNamed(const std::string& maps_dir, const std::string& name) {
  for (const PaperMap& m : loadPaperMaps(maps_dir))
    if (m.name == name || m.file() == name) return m;
  throw std::invalid_argument("no paper map '" + name + "' in " + maps_dir + "/paper_maps.json");
}

}  // namespace eaci::paper
