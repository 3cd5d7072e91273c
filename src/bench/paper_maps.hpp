// The paper's benchmark maps (Tables 1-3) with their start and goal serial numbers, and
// the numbers the paper reports for classic ACO and for EACI on each.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eaci/grid/cell.hpp"
#include "eaci/io/occupancy_map.hpp"

namespace eaci_bench {

// One row of Tables 1-3.
struct PaperRow {
  double avg_iterations = 0.0;
  double avg_length = 0.0;
  double best_length = 0.0;
  double std_length = 0.0;
  double avg_lost_ants = 0.0;
  double turn_deg = 0.0;  // total corner angle of the reported route
};

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(PaperRow, avg_iterations, avg_length, best_length, std_length, avg_lost_ants,
                                   turn_deg)

struct PaperMap {
  std::string file;                 // in the maps directory
  std::string name;                 // file without .txt
  std::string table;                // "Table 1", ... ("" for maps the paper does not report)
  std::int64_t start_serial = 0;    // the paper's 1-based serial numbers (Eq. 1-2)
  std::int64_t goal_serial = 0;
  std::optional<PaperRow> paper_aco;
  std::optional<PaperRow> paper_eaci;
  std::string note;                 // provenance remark for the report
};

// 20x20, its two alternative digitisations, 30x30, 40x40, 50x50.
const std::vector<PaperMap>& paperMaps();

const PaperMap& paperMapNamed(const std::string& name);  // throws std::invalid_argument

// A paper map read from the maps directory, with its start and goal cells.
struct LoadedPaperMap {
  PaperMap spec;
  eaci::OccupancyMap map;
  eaci::Cell start;
  eaci::Cell goal;
};

LoadedPaperMap loadPaperMap(const std::string& maps_dir, const PaperMap& spec);

}  // namespace eaci_bench
