// The exact Euclidean distance transform: for every cell, the distance from its centre to the
// centre of the nearest source cell (an obstacle), in cells.
//
// Felzenszwalb & Huttenlocher, "Distance Transforms of Sampled Functions" (Theory of Computing
// 8, 2012): one pass of the 1-D squared-distance transform (the lower envelope of parabolas)
// along every column, then one along every row. Exact, not a brushfire approximation: the
// result is min over sources of (dr^2 + dc^2), in O(width x height).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/grid_view.hpp"

namespace eaci {
namespace detail {

// The 1-D transform of `f` (n values, +inf where there is no source): d[q] = min_p (q-p)^2 + f[p].
// `v` (n ints) and `z` (n+1 doubles) are scratch space.
inline void squaredDistance1d(const double* f, double* d, int n, std::vector<int>& v, std::vector<double>& z) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const auto intersection = [&](int q, int p) {
    return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * q - 2.0 * p);
  };
  int k = -1;  // index of the rightmost parabola of the envelope
  for (int q = 0; q < n; ++q) {
    if (!std::isfinite(f[q])) continue;  // no parabola
    if (k < 0) {
      k = 0;
      v[0] = q;
      z[0] = -kInf;
      z[1] = kInf;
      continue;
    }
    double s = intersection(q, v[k]);
    while (s <= z[k]) s = intersection(q, v[--k]);  // z[0] = -inf ends the loop
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  if (k < 0) {
    for (int q = 0; q < n; ++q) d[q] = kInf;
    return;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    d[q] = dq * dq + f[v[k]];
  }
}

}  // namespace detail

// Squared Euclidean distances, in cells, from each cell centre to the nearest cell centre with
// is_source[i] != 0 (both row-major, width x height): 0 on sources, +inf everywhere if there is
// no source. Whole numbers, so exact.
inline std::vector<double> squaredDistancesToSources(int width, int height, const std::vector<std::uint8_t>& is_source) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (width <= 0 || height <= 0) return {};
  const std::size_t w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
  std::vector<double> out(w * h, kInf);
  for (std::size_t i = 0; i < out.size() && i < is_source.size(); ++i)
    if (is_source[i]) out[i] = 0.0;
  const int longest = width > height ? width : height;
  std::vector<double> f(static_cast<std::size_t>(longest)), d(static_cast<std::size_t>(longest));
  std::vector<int> v(static_cast<std::size_t>(longest));
  std::vector<double> z(static_cast<std::size_t>(longest) + 1);
  for (std::size_t c = 0; c < w; ++c) {  // columns
    for (std::size_t r = 0; r < h; ++r) f[r] = out[r * w + c];
    detail::squaredDistance1d(f.data(), d.data(), height, v, z);
    for (std::size_t r = 0; r < h; ++r) out[r * w + c] = d[r];
  }
  for (std::size_t r = 0; r < h; ++r) {  // rows, on the column results
    detail::squaredDistance1d(&out[r * w], d.data(), width, v, z);
    for (std::size_t c = 0; c < w; ++c) out[r * w + c] = d[c];
  }
  return out;
}

// Whether each cell of the view (row-major, row 0 = top) is a known obstacle: an obstacle that is
// not unknown. Unknown cells are not obstacles to measure from, as in costmap_2d's inflation.
inline std::vector<std::uint8_t> knownObstacles(const GridView& view) {
  std::vector<std::uint8_t> mask(view.cellCount(), 0);
  const CellInterpretation& interpretation = view.interpretation();
  for (int r = 0; r < view.height(); ++r) {
    for (int c = 0; c < view.width(); ++c) {
      const std::uint8_t value = view.value(Cell{r, c});
      mask[static_cast<std::size_t>(r) * static_cast<std::size_t>(view.width()) + static_cast<std::size_t>(c)] =
          value != interpretation.unknown_value && value >= interpretation.lethal_cost ? 1 : 0;
    }
  }
  return mask;
}

// Distances, in cells, from each cell centre of the view (row-major, row 0 = top) to the centre
// of the nearest known obstacle (knownObstacles); +inf everywhere on a map without obstacles.
inline std::vector<double> obstacleDistances(const GridView& view) {
  std::vector<double> d = squaredDistancesToSources(view.width(), view.height(), knownObstacles(view));
  for (double& x : d) x = std::sqrt(x);
  return d;
}

}  // namespace eaci
