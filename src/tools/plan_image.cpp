#include "plan_image.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <utility>

#include "eaci/io/text.hpp"
#include "eaci/metrics/path_metrics.hpp"

#include <stb_image_write.h>  // implementation in the linked libstb

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb/stb_easy_font.h>  // header-only, everything static
#pragma GCC diagnostic pop

namespace eaci::tools {
namespace {

struct Rgb {
  std::uint8_t r, g, b;
  friend bool operator==(Rgb a, Rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }
};

constexpr Rgb kFreeColour{255, 255, 255};
constexpr Rgb kObstacleColour{0, 0, 0};
constexpr Rgb kUnknownColour{150, 128, 178};       // unknown, planned as obstacle (violet: off the cost ramp)
constexpr Rgb kUnknownFreeColour{222, 208, 238};   // unknown, planned as passable at the dearest cost
constexpr Rgb kAuxiliaryColour{166, 186, 210};     // light blue-grey
constexpr Rgb kGridRoute{kGridRouteColour[0], kGridRouteColour[1], kGridRouteColour[2]};
constexpr Rgb kSmoothedRoute{kSmoothedRouteColour[0], kSmoothedRouteColour[1], kSmoothedRouteColour[2]};
constexpr Rgb kHaloColour{255, 255, 255};
constexpr Rgb kIslandColour{255, 140, 0};
constexpr Rgb kIslandEdge{105, 50, 0};
constexpr Rgb kStartColour{0, 165, 70};
constexpr Rgb kGoalColour{225, 0, 45};
constexpr Rgb kMarkerEdge{15, 15, 15};
constexpr Rgb kTextColour{25, 25, 25};
constexpr Rgb kLegendBackground{246, 246, 246};

Rgb mix(Rgb a, Rgb b, double t) {
  auto channel = [t](std::uint8_t x, std::uint8_t y) {
    return static_cast<std::uint8_t>(std::lround(x + (static_cast<double>(y) - x) * t));
  };
  return Rgb{channel(a.r, b.r), channel(a.g, b.g), channel(a.b, b.b)};
}

// White -> yellow -> orange -> red, t in [0, 1].
Rgb heatColour(double t) {
  static const std::pair<double, Rgb> kStops[] = {
      {0.0, {255, 255, 255}}, {0.3, {255, 242, 120}}, {0.62, {255, 165, 25}}, {1.0, {200, 20, 20}}};
  t = std::clamp(t, 0.0, 1.0);
  for (std::size_t i = 1; i < std::size(kStops); ++i) {
    if (t <= kStops[i].first) {
      const double u = (t - kStops[i - 1].first) / (kStops[i].first - kStops[i - 1].first);
      return mix(kStops[i - 1].second, kStops[i].second, u);
    }
  }
  return kStops[std::size(kStops) - 1].second;
}

class Canvas {
 public:
  Canvas(int width, int height, Rgb background)
      : width_(width), height_(height), rgb_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
    fillRect(0, 0, width, height, background);
  }

  int width() const { return width_; }
  int height() const { return height_; }

  // Later drawing is shifted by (x, y).
  void setOrigin(int x, int y) { origin_x_ = x, origin_y_ = y; }

  void blend(int x, int y, Rgb c, double alpha) {
    x += origin_x_, y += origin_y_;
    if (x < 0 || y < 0 || x >= width_ || y >= height_ || alpha <= 0) return;
    std::uint8_t* p = pixel(x, y);
    const Rgb out = alpha >= 1 ? c : mix(Rgb{p[0], p[1], p[2]}, c, alpha);
    p[0] = out.r;
    p[1] = out.g;
    p[2] = out.b;
  }

  void darken(int x, int y, double factor) {
    x += origin_x_, y += origin_y_;
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
    std::uint8_t* p = pixel(x, y);
    for (int i = 0; i < 3; ++i) p[i] = static_cast<std::uint8_t>(std::lround(p[i] * factor));
  }

  // Half-open [x0, x1) x [y0, y1), clipped.
  void fillRect(int x0, int y0, int x1, int y1, Rgb c) {
    x0 = std::max(x0, -origin_x_), y0 = std::max(y0, -origin_y_);
    x1 = std::min(x1, width_ - origin_x_), y1 = std::min(y1, height_ - origin_y_);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) blend(x, y, c, 1.0);
  }

  // Anti-aliased disc; (cx, cy) in pixel units, pixel (x, y) has its centre at (x + .5, y + .5).
  void fillDisc(double cx, double cy, double radius, Rgb c) {
    const int x0 = static_cast<int>(std::floor(cx - radius - 1)), x1 = static_cast<int>(std::ceil(cx + radius + 1));
    const int y0 = static_cast<int>(std::floor(cy - radius - 1)), y1 = static_cast<int>(std::ceil(cy + radius + 1));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
        blend(x, y, c, std::clamp(radius + 0.5 - d, 0.0, 1.0));
      }
  }

  // Anti-aliased polyline of the given width with round joins and caps. The coverage of all
  // segments is combined (max) before blending, so joints are not painted twice.
  void strokePolyline(const std::vector<std::pair<double, double>>& points, double width, Rgb c) {
    if (points.empty()) return;
    const double half = width / 2.0;
    double min_x = points[0].first, max_x = min_x, min_y = points[0].second, max_y = min_y;
    for (const auto& p : points) {
      min_x = std::min(min_x, p.first), max_x = std::max(max_x, p.first);
      min_y = std::min(min_y, p.second), max_y = std::max(max_y, p.second);
    }
    const int bx0 = std::max(-origin_x_, static_cast<int>(std::floor(min_x - half - 1)));
    const int by0 = std::max(-origin_y_, static_cast<int>(std::floor(min_y - half - 1)));
    const int bx1 = std::min(width_ - origin_x_ - 1, static_cast<int>(std::ceil(max_x + half + 1)));
    const int by1 = std::min(height_ - origin_y_ - 1, static_cast<int>(std::ceil(max_y + half + 1)));
    if (bx1 < bx0 || by1 < by0) return;
    const int bw = bx1 - bx0 + 1, bh = by1 - by0 + 1;
    std::vector<std::uint8_t> coverage(static_cast<std::size_t>(bw) * static_cast<std::size_t>(bh), 0);
    auto stamp = [&](std::pair<double, double> a, std::pair<double, double> b) {
      const double dx = b.first - a.first, dy = b.second - a.second, len2 = dx * dx + dy * dy;
      const int x0 = std::max(bx0, static_cast<int>(std::floor(std::min(a.first, b.first) - half - 1)));
      const int x1 = std::min(bx1, static_cast<int>(std::ceil(std::max(a.first, b.first) + half + 1)));
      const int y0 = std::max(by0, static_cast<int>(std::floor(std::min(a.second, b.second) - half - 1)));
      const int y1 = std::min(by1, static_cast<int>(std::ceil(std::max(a.second, b.second) + half + 1)));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const double px = x + 0.5 - a.first, py = y + 0.5 - a.second;
          const double t = len2 > 0 ? std::clamp((px * dx + py * dy) / len2, 0.0, 1.0) : 0.0;
          const double d = std::hypot(px - t * dx, py - t * dy);
          const double alpha = std::clamp(half + 0.5 - d, 0.0, 1.0);
          auto& slot = coverage[static_cast<std::size_t>(y - by0) * static_cast<std::size_t>(bw) +
                                static_cast<std::size_t>(x - bx0)];
          slot = std::max<std::uint8_t>(slot, static_cast<std::uint8_t>(std::lround(alpha * 255)));
        }
    };
    if (points.size() == 1) stamp(points[0], points[0]);
    for (std::size_t i = 1; i < points.size(); ++i) stamp(points[i - 1], points[i]);
    for (int y = by0; y <= by1; ++y)
      for (int x = bx0; x <= bx1; ++x) {
        const std::uint8_t a =
            coverage[static_cast<std::size_t>(y - by0) * static_cast<std::size_t>(bw) + static_cast<std::size_t>(x - bx0)];
        if (a) blend(x, y, c, a / 255.0);
      }
  }

  RgbImage release() && { return RgbImage{width_, height_, std::move(rgb_)}; }

 private:
  std::uint8_t* pixel(int x, int y) {
    return &rgb_[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 3];
  }

  int width_;
  int height_;
  int origin_x_ = 0;
  int origin_y_ = 0;
  std::vector<std::uint8_t> rgb_;
};

// stb_easy_font knows printable ASCII only.
std::vector<char> fontText(const std::string& text) {
  std::vector<char> out;
  out.reserve(text.size() + 1);
  for (char ch : text) out.push_back(ch >= 32 && ch < 127 ? ch : '?');
  out.push_back('\0');
  return out;
}

int textWidth(const std::string& text, int scale) {
  std::vector<char> buffer = fontText(text);
  return stb_easy_font_width(buffer.data()) * scale;
}

constexpr int kGlyphHeight = 7;  // stb_easy_font capitals are 7 units tall

// Text with its top-left corner at (x, y), each font unit `scale` pixels.
void drawText(Canvas& canvas, int x, int y, const std::string& text, int scale, Rgb colour) {
  std::vector<char> buffer = fontText(text);
  std::vector<char> vertices(text.size() * 1024 + 64);  // up to ~10 quads of 64 bytes per glyph
  const int quads = stb_easy_font_print(0, 0, buffer.data(), nullptr, vertices.data(), static_cast<int>(vertices.size()));
  for (int q = 0; q < quads; ++q) {
    float v[12];  // 4 vertices of x, y, z, rgba (16 bytes each); we need vertex 0 and 2
    std::memcpy(&v[0], vertices.data() + static_cast<std::size_t>(q) * 64, 12);
    std::memcpy(&v[4], vertices.data() + static_cast<std::size_t>(q) * 64 + 32, 12);
    canvas.fillRect(x + static_cast<int>(std::lround(v[0] * scale)), y + static_cast<int>(std::lround(v[1] * scale)),
                    x + static_cast<int>(std::lround(v[4] * scale)), y + static_cast<int>(std::lround(v[5] * scale)),
                    colour);
  }
}

// Centres a short label (an island number, "S", "G") on a point.
void drawCentredText(Canvas& canvas, double cx, double cy, const std::string& text, int scale, Rgb colour) {
  const int w = textWidth(text, scale) - scale;  // the advance includes one unit of spacing
  drawText(canvas, static_cast<int>(std::lround(cx - w / 2.0)),
           static_cast<int>(std::lround(cy - kGlyphHeight * scale / 2.0)), text, scale, colour);
}

// A disc with a dark rim, optionally with a white ring between, and a centred label if it fits.
void drawMarker(Canvas& canvas, double cx, double cy, double radius, Rgb fill, Rgb edge, bool ring,
                const std::string& label, Rgb label_colour) {
  const double rim = std::max(1.0, radius * 0.14);
  canvas.fillDisc(cx, cy, radius + rim, edge);
  if (ring) {
    canvas.fillDisc(cx, cy, radius, kHaloColour);
    canvas.fillDisc(cx, cy, radius - rim, fill);
  } else {
    canvas.fillDisc(cx, cy, radius, fill);
  }
  if (label.empty()) return;
  const int scale = radius >= 16 ? 2 : 1;
  const double inner = 2 * (radius - (ring ? rim : 0.0));
  if (textWidth(label, scale) + 1 <= inner && kGlyphHeight * scale + 2 <= inner)
    drawCentredText(canvas, cx, cy, label, scale, label_colour);
}

enum class Swatch { kDisc, kSquare, kLine, kGradient, kCostRamp };

struct LegendItem {
  Swatch swatch;
  Rgb colour;
  std::string label;
  double line_width = 3;  // kLine: in text-scale units
};

struct LegendLayout {
  std::vector<std::vector<std::size_t>> rows;  // item indices per row
};

}  // namespace

std::vector<std::string> routeCaptionLines(const PlanResult& r, double resolution, bool smoothed) {
  auto describe = [resolution](const std::string& name, double length, double turn) {
    std::string line = name + ": " + formatNumber(length, 2) + " cells";
    if (resolution != 1.0) line += " = " + formatNumber(length * resolution, 2) + " m";
    return line + ", total turn " + formatNumber(turn, 0) + " deg";
  };
  if (!smoothed) return {describe("route", r.length, r.total_turn_deg)};
  return {describe("grid route (8-connected)", r.length, r.total_turn_deg),
          describe("smoothed route (driven)", r.smoothed_length, totalTurnDegrees(r.smoothed_path))};
}

int cellPixels(int width, int height) {
  const int longest = std::max({width, height, 1});
  return std::clamp(1000 / longest, 1, 24);
}

PlanImage renderPlan(const PlanDrawing& d) {
  if (d.map == nullptr || d.map->width <= 0 || d.map->height <= 0 ||
      d.map->cells.size() != static_cast<std::size_t>(d.map->width) * static_cast<std::size_t>(d.map->height))
    throw std::invalid_argument("renderPlan: no map to draw");
  const OccupancyMap& map = *d.map;
  const PlanResult* result = d.result;
  const int k = cellPixels(map.width, map.height);
  const int map_w = map.width * k, map_h = map.height * k;
  const std::size_t cells = map.cells.size();
  const GridView map_view = map.view(d.unknown, d.lethal_cost);
  const GridView view = d.planned_on ? *d.planned_on : map_view;

  // ---- pheromone heat: log scale over the cells that carry more than the floor
  std::vector<double> heat;  // per cell, 0 = none, else (0, 1]
  if (result && result->pheromone.size() == cells) {
    constexpr double kDecades = 6.0;  // fainter than max / 10^6 is not drawn
    double hi = -std::numeric_limits<double>::infinity(), lo = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < cells; ++i) {
      const double p = result->pheromone[i];
      if (!(p > kPheromoneFloor * 1.5) || !std::isfinite(p) || view.isObstacle(Cell{int(i / map.width), int(i % map.width)}))
        continue;
      hi = std::max(hi, std::log10(p));
      lo = std::min(lo, std::log10(p));
    }
    if (std::isfinite(hi)) {
      lo = std::max(lo, hi - kDecades);
      heat.assign(cells, 0.0);
      for (std::size_t i = 0; i < cells; ++i) {
        const double p = result->pheromone[i];
        if (!(p > kPheromoneFloor * 1.5) || !std::isfinite(p)) continue;
        const double t = hi - lo > 1e-12 ? (std::log10(p) - lo) / (hi - lo) : 1.0;
        if (t >= 0) heat[i] = 0.15 + 0.85 * std::min(t, 1.0);  // the faintest trail is still pale yellow
      }
    }
  }
  const bool has_aux = d.auxiliary_blocked.size() == cells &&
                       std::any_of(d.auxiliary_blocked.begin(), d.auxiliary_blocked.end(), [](auto v) { return v != 0; });
  bool has_unknown = false, has_cost = false;
  for (std::uint8_t v : map.cells) has_unknown = has_unknown || v == kUnknownValue;
  for (int r = 0; r < map.height && !has_cost; ++r)
    for (int c = 0; c < map.width && !has_cost; ++c) has_cost = view.isFree(Cell{r, c}) && view.cost(Cell{r, c}) > 0;

  // ---- legend below the map
  const int ts = map_w >= 600 ? 2 : 1;  // text scale
  const int pad = 5 * ts, line_h = 12 * ts;
  std::vector<std::string> caption_lines;
  {
    std::string line;
    for (char ch : d.caption) {
      if (ch == '\n') caption_lines.push_back(line), line.clear();
      else line += ch;
    }
    if (!line.empty()) caption_lines.push_back(line);
  }
  std::vector<LegendItem> items = {{Swatch::kDisc, kStartColour, "start"}, {Swatch::kDisc, kGoalColour, "goal"}};
  const bool has_path = result && !result->path.empty();
  const bool has_smoothed = has_path && d.smoothed && !result->smoothed_path.empty();
  const bool has_islands = result && result->islands.size() > 2;
  auto centre = [k](Cell c) { return std::pair<double, double>{(c.col + 0.5) * k, (c.row + 0.5) * k}; };
  auto on_map = [&](Cell c) { return c.row >= 0 && c.col >= 0 && c.row < map.height && c.col < map.width; };

  // Cells of a few pixels (large maps): widths and markers follow the picture's size rather
  // than the cell's, the islands go under the path, and only islands some distance apart are
  // drawn, so that the route stays visible.
  const bool small_cells = k < 6;
  const double picture = std::max(map_w, map_h);
  const double path_w = small_cells ? std::max(3.0, picture / 400.0) : std::max(3.0, 0.3 * k);
  const double island_r = small_cells ? std::max(3.0, picture / 300.0) : std::max(3.5, 0.4 * k);
  std::vector<std::size_t> islands_drawn;  // indices into result->islands
  if (has_islands) {
    std::vector<std::pair<double, double>> centres;
    std::vector<std::size_t> index;
    for (std::size_t z = 1; z + 1 < result->islands.size(); ++z) {
      if (!on_map(result->islands[z])) continue;
      centres.push_back(centre(result->islands[z]));
      index.push_back(z);
    }
    for (std::size_t kept : thinMarkers(centres, small_cells ? 8.0 * island_r : 0.0)) islands_drawn.push_back(index[kept]);
  }
  const std::size_t island_count = has_islands ? result->islands.size() - 2 : 0;
  if (has_smoothed) {
    items.push_back({Swatch::kLine, kGridRoute, "grid route (8-connected)", 6});
    items.push_back({Swatch::kLine, kSmoothedRoute, "smoothed route (what a robot drives)"});
  } else if (has_path) {
    items.push_back({Swatch::kLine, kGridRoute, "route"});
  }
  if (has_islands)
    items.push_back({Swatch::kDisc, kIslandColour,
                     islands_drawn.size() < island_count
                         ? "island (order; " + std::to_string(islands_drawn.size()) + " of " +
                               std::to_string(island_count) + " drawn)"
                         : std::string("island (order)")});
  if (!heat.empty()) items.push_back({Swatch::kGradient, kGridRoute, "pheromone (log scale)"});
  if (has_aux) items.push_back({Swatch::kSquare, kAuxiliaryColour, "corner closed (auxiliary map)"});
  if (has_cost) items.push_back({Swatch::kCostRamp, kFreeColour, "cell cost 0..254"});
  items.push_back({Swatch::kSquare, kObstacleColour, "obstacle"});
  if (has_unknown)
    items.push_back({Swatch::kSquare, d.unknown == UnknownPolicy::kExpensive ? kUnknownFreeColour : kUnknownColour,
                     d.unknown == UnknownPolicy::kExpensive ? "unknown (passable, dearest cost)" : "unknown"});
  auto swatch_width = [&](const LegendItem& item) {
    return (item.swatch == Swatch::kGradient || item.swatch == Swatch::kCostRamp ? 36 : item.swatch == Swatch::kLine ? 20 : 12) *
           ts;
  };
  auto item_width = [&](const LegendItem& item) {
    return swatch_width(item) + 4 * ts + textWidth(item.label, ts) + 10 * ts;
  };
  // A margin around the map keeps the start and goal markers whole on corner cells.
  const double marker_r = std::max(8.0, 0.62 * k);
  const int margin = std::max(static_cast<int>(std::ceil(marker_r * 1.14)) + 3, pad);
  int canvas_w = std::max(map_w + 2 * margin, 200 * ts);
  for (const auto& line : caption_lines) canvas_w = std::max(canvas_w, textWidth(line, ts) + 2 * margin);
  LegendLayout layout;
  {
    int x = margin;
    layout.rows.emplace_back();
    for (std::size_t i = 0; i < items.size(); ++i) {
      const int w = item_width(items[i]);
      if (x + w > canvas_w - margin && !layout.rows.back().empty()) {
        layout.rows.emplace_back();
        x = margin;
      }
      layout.rows.back().push_back(i);
      x += w;
    }
  }
  const int legend_h = static_cast<int>(caption_lines.size() + layout.rows.size()) * line_h + pad;
  Canvas canvas(canvas_w, margin + map_h + margin + legend_h, kLegendBackground);
  canvas.setOrigin(margin, margin);

  // ---- cells
  for (int r = 0; r < map.height; ++r) {
    for (int c = 0; c < map.width; ++c) {
      const Cell cell{r, c};
      const std::size_t i = static_cast<std::size_t>(r) * static_cast<std::size_t>(map.width) + static_cast<std::size_t>(c);
      const bool unknown = map.cells[i] == kUnknownValue;
      const bool obstacle = map_view.isObstacle(cell);
      const bool planned_obstacle = !obstacle && view.isObstacle(cell);  // e.g. the inscribed band of --inflate
      const std::uint8_t grey = obstacle ? 0 : planned_obstacle ? costGrey(254) : costGrey(view.cost(cell));
      Rgb colour = obstacle ? (unknown ? kUnknownColour : kObstacleColour)
                            : (unknown ? kUnknownFreeColour : Rgb{grey, grey, grey});
      if (!obstacle) {
        if (has_aux && d.auxiliary_blocked[i]) colour = kAuxiliaryColour;
        else if (!heat.empty() && heat[i] > 0) colour = unknown ? mix(heatColour(heat[i]), colour, 0.3) : heatColour(heat[i]);
        if (grey < 255 && !unknown && !(colour == Rgb{grey, grey, grey})) colour = mix(colour, Rgb{0, 0, 0}, 1.0 - grey / 255.0);
      }
      canvas.fillRect(c * k, r * k, (c + 1) * k, (r + 1) * k, colour);
    }
  }
  if (k >= 8) {  // thin grid lines: darken the first pixel row / column of every cell
    for (int y = 0; y < map_h; ++y)
      for (int x = 0; x < map_w; ++x)
        if (x % k == 0 || y % k == 0) canvas.darken(x, y, 0.86);
  }
  for (int x = 0; x < map_w; ++x) canvas.darken(x, map_h - 1, 0.7), canvas.darken(x, 0, 0.9);  // frame
  for (int y = 0; y < map_h; ++y) canvas.darken(map_w - 1, y, 0.7), canvas.darken(0, y, 0.9);

  // ---- path, islands, start, goal
  auto draw_islands = [&] {
    for (std::size_t z : islands_drawn) {
      const auto [x, y] = centre(result->islands[z]);
      drawMarker(canvas, x, y, island_r, kIslandColour, kIslandEdge, false, std::to_string(z), kTextColour);
    }
  };
  if (small_cells) draw_islands();
  // A route: its line on a white halo that keeps it apart from the pheromone beneath.
  auto draw_route = [&](const CellPath& route, double width, double halo, Rgb colour) {
    std::vector<std::pair<double, double>> points;
    for (const Cell& c : route) points.push_back(centre(c));
    if (halo > 0) canvas.strokePolyline(points, width + halo, kHaloColour);
    canvas.strokePolyline(points, width, colour);
  };
  const double halo = std::max(2.0, small_cells ? path_w * 0.6 : 0.16 * k);
  // With a smoothed route the grid route is a wide line and the smoothed route a narrow one
  // on top of it: where the two coincide the smoothed route runs inside the grid route's band,
  // where they part both show.
  if (has_smoothed) {
    draw_route(result->path, 2.3 * path_w, halo, kGridRoute);
    if (!small_cells) draw_islands();
    draw_route(result->smoothed_path, std::max(2.5, 0.9 * path_w), 1.0, kSmoothedRoute);
  } else {
    if (has_path) draw_route(result->path, path_w, halo, kGridRoute);
    if (!small_cells) draw_islands();
  }
  if (d.start && on_map(*d.start)) {
    const auto [x, y] = centre(*d.start);
    drawMarker(canvas, x, y, marker_r, kStartColour, kMarkerEdge, true, "S", kHaloColour);
  }
  if (d.goal && on_map(*d.goal)) {
    const auto [x, y] = centre(*d.goal);
    drawMarker(canvas, x, y, marker_r, kGoalColour, kMarkerEdge, true, "G", kHaloColour);
  }

  // ---- legend
  canvas.setOrigin(0, 0);
  int y = margin + map_h + margin / 2;
  for (const auto& line : caption_lines) {
    drawText(canvas, margin, y + (line_h - kGlyphHeight * ts) / 2, line, ts, kTextColour);
    y += line_h;
  }
  for (const auto& row : layout.rows) {
    int x = margin;
    const int mid = y + line_h / 2;
    for (std::size_t i : row) {
      const LegendItem& item = items[i];
      const int sw = swatch_width(item);
      switch (item.swatch) {
        case Swatch::kDisc:
          canvas.fillDisc(x + sw / 2.0, mid, sw / 2.0, item.colour == kIslandColour ? kIslandEdge : kMarkerEdge);
          canvas.fillDisc(x + sw / 2.0, mid, sw / 2.0 - ts, item.colour);
          break;
        case Swatch::kSquare:
          canvas.fillRect(x, mid - sw / 2, x + sw, mid + sw / 2, kMarkerEdge);
          canvas.fillRect(x + 1, mid - sw / 2 + 1, x + sw - 1, mid + sw / 2 - 1, item.colour);
          break;
        case Swatch::kLine: {  // round caps: the ends stay inside the swatch
          const double half = item.line_width * ts / 2.0;
          canvas.strokePolyline({{x + half, mid + 0.0}, {x + sw - half, mid + 0.0}}, item.line_width * ts, item.colour);
          break;
        }
        case Swatch::kGradient:
          for (int g = 0; g < sw; ++g)
            canvas.fillRect(x + g, mid - 4 * ts, x + g + 1, mid + 4 * ts, heatColour(0.15 + 0.85 * g / (sw - 1.0)));
          break;
        case Swatch::kCostRamp:
          canvas.fillRect(x - 1, mid - 4 * ts - 1, x + sw + 1, mid + 4 * ts + 1, kMarkerEdge);
          for (int g = 0; g < sw; ++g) {
            const std::uint8_t grey = costGrey(static_cast<std::uint8_t>(std::lround(254.0 * g / (sw - 1.0))));
            canvas.fillRect(x + g, mid - 4 * ts, x + g + 1, mid + 4 * ts, Rgb{grey, grey, grey});
          }
          break;
      }
      drawText(canvas, x + sw + 4 * ts, mid - kGlyphHeight * ts / 2, item.label, ts, kTextColour);
      x += item_width(item);
    }
    y += line_h;
  }
  return PlanImage{std::move(canvas).release(), margin, margin, k};
}

void writePng(const std::string& file, const RgbImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
    throw std::runtime_error("cannot write PNG '" + file + "': empty image");
  errno = 0;
  if (!stbi_write_png(file.c_str(), image.width, image.height, 3, image.rgb.data(), image.width * 3)) {
    const int error = errno;
    throw std::runtime_error("cannot write PNG '" + file + "'" + (error ? std::string(": ") + std::strerror(error) : ""));
  }
}

}  // namespace eaci::tools
