#include "map_generator.hpp"

#include <algorithm>
#include <utility>
#include <stdexcept>
#include <vector>

#include "eaci/random.hpp"
#include "eaci/io/occupancy_map.hpp"
#include "eaci/grid/cost_grid.hpp"
#include "eaci/search/astar.hpp"

namespace eaci_bench {

namespace {

// A perfect maze (one route between any two free cells) drawn by a randomized depth-first
// search (recursive backtracker, with an explicit stack) on a lattice of square maze cells:
// maze cell (i, j) is the free square of `corridor` x `corridor` grid cells whose top-left is
// (i * pitch, j * pitch), pitch = corridor + wall; between two neighbouring maze cells lies a
// wall `wall` cells thick, opened over the full corridor width where the search passed.
// Wall crossings stay occupied. The lattice has m = (size + wall) / pitch maze cells a side;
// rows and columns past m * pitch - wall are walls.
struct MazeLayout {
  int size = 0;      // grid cells a side
  int corridor = 3;  // free width of a corridor, cells
  int wall = 1;      // wall thickness, cells
  int pitch() const { return corridor + wall; }
  int cellsPerSide() const { return (size + wall) / pitch(); }  // m
  int lastFree() const { return cellsPerSide() * pitch() - wall - 1; }  // last free row and column
};

void fill(std::vector<std::uint8_t>& cells, int size, int top, int left, int height, int width) {
  for (int r = top; r < top + height; ++r)
    for (int c = left; c < left + width; ++c) cells[static_cast<std::size_t>(r) * size + c] = eaci::kFreeValue;
}

std::vector<std::uint8_t> drawMaze(const MazeLayout& layout, std::uint64_t seed) {
  const int n = layout.size, m = layout.cellsPerSide(), p = layout.pitch(), corridor = layout.corridor;
  if (corridor < 1 || layout.wall < 1 || m < 1) throw std::runtime_error("maze: corridor and wall >= 1 cell, and room for one maze cell");
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(n) * n, eaci::kOccupiedValue);
  eaci::SplitMix64 rng(seed ^ 0xBB67AE8584CAA73BULL);
  std::vector<char> visited(static_cast<std::size_t>(m) * m, 0);
  std::vector<std::pair<int, int>> stack{{0, 0}};
  visited[0] = 1;
  fill(cells, n, 0, 0, corridor, corridor);
  constexpr int kStep[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    int open[4], count = 0;
    for (int d = 0; d < 4; ++d) {
      const int ni = i + kStep[d][0], nj = j + kStep[d][1];
      if (ni >= 0 && ni < m && nj >= 0 && nj < m && !visited[static_cast<std::size_t>(ni) * m + nj]) open[count++] = d;
    }
    if (count == 0) {
      stack.pop_back();
      continue;
    }
    const int d = open[rng.next() % static_cast<std::uint64_t>(count)];
    const int ni = i + kStep[d][0], nj = j + kStep[d][1];
    visited[static_cast<std::size_t>(ni) * m + nj] = 1;
    fill(cells, n, ni * p, nj * p, corridor, corridor);
    // The wall between (i, j) and (ni, nj), opened over the corridor's width.
    if (ni != i) fill(cells, n, std::min(i, ni) * p + corridor, j * p, layout.wall, corridor);
    else fill(cells, n, i * p, std::min(j, nj) * p + corridor, corridor, layout.wall);
    stack.emplace_back(ni, nj);
  }
  return cells;
}

constexpr double kClutterMin = 0.20, kClutterMax = 0.30;  // obstacle fraction
constexpr int kCornerKeepFree = 3;                        // free square at start and goal
constexpr int kMaxAttempts = 100;

// Uniform integers and reals from SplitMix64 (specified output, unlike std:: distributions).
class Random {
 public:
  explicit Random(std::uint64_t seed) : rng_(seed ^ 0x6A09E667F3BCC909ULL) {}
  int between(int lo, int hi) {  // inclusive
    return lo + static_cast<int>(rng_.next() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  double between(double lo, double hi) { return lo + (hi - lo) * rng_.uniform(); }

 private:
  eaci::SplitMix64 rng_;
};

class Canvas {
 public:
  explicit Canvas(int size) : size_(size), cells_(static_cast<std::size_t>(size) * size, eaci::kFreeValue) {}
  int size() const { return size_; }
  void set(int row, int col, bool obstacle) {
    cells_[static_cast<std::size_t>(row) * size_ + col] = obstacle ? eaci::kOccupiedValue : eaci::kFreeValue;
  }
  bool isObstacle(int row, int col) const {
    return cells_[static_cast<std::size_t>(row) * size_ + col] == eaci::kOccupiedValue;
  }
  std::vector<std::uint8_t> release() { return std::move(cells_); }

 private:
  int size_;
  std::vector<std::uint8_t> cells_;
};

// Wall positions along one axis: rooms room_min..room_max wide, none closer than room_min to the far edge.
std::vector<int> wallLines(int size, Random& random, const GeneratorOptions& options) {
  std::vector<int> walls;
  for (int pos = random.between(options.room_min, options.room_max); pos <= size - 1 - options.room_min;
       pos += 1 + random.between(options.room_min, options.room_max))
    walls.push_back(pos);
  return walls;
}

// Spans [first, last] between consecutive walls (and the map edges).
std::vector<std::pair<int, int>> spansBetween(const std::vector<int>& walls, int size) {
  std::vector<std::pair<int, int>> spans;
  int first = 0;
  for (int wall : walls) {
    spans.emplace_back(first, wall - 1);
    first = wall + 1;
  }
  spans.emplace_back(first, size - 1);
  return spans;
}

// One door, door_min..door_max cells wide, somewhere in [first, last] of a wall.
std::pair<int, int> doorIn(std::pair<int, int> span, Random& random, const GeneratorOptions& options) {
  const int width = std::min(random.between(options.door_min, options.door_max), span.second - span.first + 1);
  const int begin = random.between(span.first, span.second - width + 1);
  return {begin, begin + width - 1};
}

void drawRooms(Canvas& canvas, Random& random, const GeneratorOptions& options) {
  const int n = canvas.size();
  const std::vector<int> rows = wallLines(n, random, options), cols = wallLines(n, random, options);
  for (int r : rows)
    for (int c = 0; c < n; ++c) canvas.set(r, c, true);
  for (int c : cols)
    for (int r = 0; r < n; ++r) canvas.set(r, c, true);
  // A door in every wall segment between two rooms: every room reaches every neighbour.
  for (int r : rows)
    for (const auto& span : spansBetween(cols, n)) {
      const auto door = doorIn(span, random, options);
      for (int c = door.first; c <= door.second; ++c) canvas.set(r, c, false);
    }
  for (int c : cols)
    for (const auto& span : spansBetween(rows, n)) {
      const auto door = doorIn(span, random, options);
      for (int r = door.first; r <= door.second; ++r) canvas.set(r, c, false);
    }
}

bool nearCorner(int row, int col, int n) {
  const auto near = [&](int v, int corner) { return std::abs(v - corner) < kCornerKeepFree; };
  return (near(row, 0) && near(col, 0)) || (near(row, n - 1) && near(col, n - 1));
}

void drawClutter(Canvas& canvas, Random& random) {
  const int n = canvas.size();
  const int max_side = std::max(4, n / 10);
  const auto target = static_cast<long long>(random.between(kClutterMin, kClutterMax) * n * n);
  long long blocked = 0;
  while (blocked < target) {
    const int h = random.between(2, max_side), w = random.between(2, max_side);
    const int top = random.between(0, n - h), left = random.between(0, n - w);
    for (int r = top; r < top + h; ++r)
      for (int c = left; c < left + w; ++c) {
        if (canvas.isObstacle(r, c) || nearCorner(r, c, n)) continue;
        canvas.set(r, c, true);
        ++blocked;
      }
  }
}

eaci::OccupancyMap toMap(Canvas& canvas) {
  eaci::OccupancyMap map;
  map.width = map.height = canvas.size();
  map.cells = canvas.release();
  return map;
}

double obstacleFraction(const eaci::OccupancyMap& map) {
  const auto blocked = std::count(map.cells.begin(), map.cells.end(), eaci::kOccupiedValue);
  return static_cast<double>(blocked) / static_cast<double>(map.cells.size());
}

}  // namespace

const char* toString(MapKind kind) {
  switch (kind) {
    case MapKind::kRooms: return "rooms";
    case MapKind::kClutter: return "clutter";
    case MapKind::kMaze: return "maze";
  }
  return "?";
}

bool parseMapKind(const std::string& text, MapKind& kind) {
  if (text == "rooms") kind = MapKind::kRooms;
  else if (text == "clutter") kind = MapKind::kClutter;
  else if (text == "maze") kind = MapKind::kMaze;
  else return false;
  return true;
}

std::string generatorOptionsProblem(const GeneratorOptions& options) {
  if (options.door_min < 1 || options.door_max < options.door_min)
    return "door widths must be 1 <= min <= max cells (got " + std::to_string(options.door_min) + "-" +
           std::to_string(options.door_max) + ")";
  if (options.room_min < 1 || options.room_max < options.room_min)
    return "room widths must be 1 <= min <= max cells (got " + std::to_string(options.room_min) + "-" +
           std::to_string(options.room_max) + ")";
  if (options.corridor < 1 || options.maze_wall < 1)
    return "maze corridor and wall widths must be >= 1 cell (got " + std::to_string(options.corridor) + ", " +
           std::to_string(options.maze_wall) + ")";
  return "";
}

GeneratedMap generateMap(MapKind kind, int size, std::uint64_t seed, const GeneratorOptions& options) {
  if (size < 2 * kCornerKeepFree) throw std::runtime_error("map size must be at least 6");
  const std::string problem = generatorOptionsProblem(options);
  if (!problem.empty()) throw std::runtime_error(problem);
  for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
    GeneratedMap g;
    g.kind = kind;
    g.size = size;
    g.seed = seed;
    g.seed_used = seed + static_cast<std::uint64_t>(attempt);
    Random random(g.seed_used * 1000003ULL + static_cast<std::uint64_t>(size) * 2 + (kind == MapKind::kRooms ? 0 : 1));
    Canvas canvas(size);
    if (kind == MapKind::kRooms) drawRooms(canvas, random, options);
    else if (kind == MapKind::kClutter) drawClutter(canvas, random);
    g.map = toMap(canvas);
    g.start = eaci::Cell{0, 0};
    g.goal = eaci::Cell{size - 1, size - 1};
    if (kind == MapKind::kMaze) {
      const MazeLayout layout{size, options.corridor, options.maze_wall};
      if (layout.cellsPerSide() < 1) throw std::runtime_error("maze: the map is narrower than one corridor");
      g.map.cells = drawMaze(layout, g.seed_used * 1000003ULL + static_cast<std::uint64_t>(size));
      g.goal = eaci::Cell{layout.lastFree(), layout.lastFree()};
    }
    g.obstacle_fraction = obstacleFraction(g.map);
    const eaci::CostGrid grid = eaci::CostGrid::fromView(g.map.view(), false);
    const eaci::CheapestPath shortest = eaci::cheapestPath(grid, g.start, g.goal);
    if (!shortest.found) continue;
    g.optimum = shortest.length;
    return g;
  }
  throw std::runtime_error(std::string("no connected ") + toString(kind) + " map of size " + std::to_string(size) +
                           " in " + std::to_string(kMaxAttempts) + " seeds from " + std::to_string(seed));
}

}  // namespace eaci_bench
