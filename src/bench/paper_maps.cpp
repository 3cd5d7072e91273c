#include "paper_maps.hpp"

#include <stdexcept>

#include "eaci/grid/cell_numbering.hpp"
#include "eaci/io/map_io.hpp"

namespace eaci_bench {

namespace {

// Columns of Tables 1-3: average iterations, average length, best length, standard
// deviation, average lost ants, total corner angle (degrees).
PaperRow row(double iterations, double avg_length, double best_length, double std_length, double lost, double turn) {
  return PaperRow{iterations, avg_length, best_length, std_length, lost, turn};
}

}  // namespace

const std::vector<PaperMap>& paperMaps() {
  static const std::vector<PaperMap> maps = {
      {"paper-20x20.txt", "paper-20x20", "Table 1", 1, 400, row(40.5, 30.97, 30.97, 0.0, 1246.0, 675),
       row(1, 30.97, 30.97, 0.0, 9.85, 675), "Winsleo/ant_colony_plan AntPlan/improved_ant.m (a likely match)"},
      {"paper-20x20-alt-a.txt", "paper-20x20-alt-a", "", 1, 400, std::nullopt, std::nullopt,
       "hand digitisation a, dvnam1605/MAACO-path-planing env.py"},
      {"paper-20x20-alt-b.txt", "paper-20x20-alt-b", "", 1, 400, std::nullopt, std::nullopt,
       "hand digitisation b, dvnam1605/MAACO-path-planing env.py"},
      {"paper-30x30.txt", "paper-30x30", "Table 2", 871, 30, row(77.1, 45.89, 45.36, 1.6564, 3112.4, 675),
       row(1.4, 44.53, 44.53, 0.0, 27.5, 765), "LiDongDong1996/IQACO res/map_base_30.txt (exact)"},
      {"paper-40x40.txt", "paper-40x40", "Table 3", 1, 1600, row(100, 65.34, 63.94, 2.1236, 3993.8, 900),
       row(6.2, 60.21, 59.25, 0.2335, 47.6, 585), "LiDongDong1996/IQACO res/map_base_40.txt (probable)"},
      {"paper-50x50.txt", "paper-50x50", "Table 3", 2451, 50, row(100, 84.64, 81.59, 2.5233, 3988.7, 630),
       row(7.1, 74.54, 72.81, 0.2704, 99.2, 585), "LiDongDong1996/IQACO res/map_base_50.txt (exact)"},
  };
  return maps;
}

const PaperMap& paperMapNamed(const std::string& name) {
  for (const PaperMap& m : paperMaps())
    if (m.name == name) return m;
  throw std::invalid_argument("unknown paper map '" + name + "'");
}

LoadedPaperMap loadPaperMap(const std::string& maps_dir, const PaperMap& spec) {
  LoadedPaperMap m;
  m.spec = spec;
  m.map = eaci::loadMatrixText(maps_dir + "/" + spec.file);
  m.start = eaci::cellFromSerial(spec.start_serial, m.map.width);
  m.goal = eaci::cellFromSerial(spec.goal_serial, m.map.width);
  return m;
}

}  // namespace eaci_bench
