// Pheromone on the directed edges of the grid: tau(i, d) for the move from cell i in direction d,
// with the factor tau^alpha of Eq. 8 kept alongside so an ant's step costs no pow().
//
// Evaporation multiplies every edge by the same factor, so it is kept as one common scale
// instead of a pass over all edges (on an 800 x 800 map that pass would cost more than all
// the ants' walks): tau = scale * stored, tau^alpha = scale^alpha * stored^alpha. Reads apply
// the floor, so every edge behaves as if clamped to kPheromoneFloor after each update.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "eaci/grid/moves.hpp"

namespace eaci {

// Pheromone never drops below this, so that Eq. 8 stays defined after the penalty of Eq. 24.
constexpr double kPheromoneFloor = 1e-10;

// Ant colonies keep two doubles per directed edge: 128 bytes per cell of the cells they work
// on. A colony that would need more than this is refused (about 16.7 million cells, e.g.
// 4096 x 4096): on the whole map (classic ACO, the paper's islands, region_margin 0) by
// eaci::plan from the map's size, around a route (geodesic EACI) when its region is built
// (ColonyRegion::aroundRoute's max_cells).
constexpr std::size_t kMaxPheromoneBytes = std::size_t{2} << 30;
constexpr std::size_t kPheromoneBytesPerCell = 2 * sizeof(double) * kDirections;
constexpr std::size_t kMaxPheromoneCells = kMaxPheromoneBytes / kPheromoneBytesPerCell;

class PheromoneField {
 public:
  PheromoneField() = default;
  PheromoneField(std::size_t cell_count, double initial, double alpha) { reset(cell_count, initial, alpha); }

  // Every edge of `cell_count` cells at `initial` again, in the memory this field already holds
  // where it is enough (a planner that keeps its fields between plans allocates no new one).
  void reset(std::size_t cell_count, double initial, double alpha) {
    alpha_ = alpha;
    floor_weight_ = std::pow(kPheromoneFloor, alpha);
    scale_ = weight_scale_ = 1.0;
    stored_.assign(cell_count * kDirections, std::max(initial, kPheromoneFloor));
    stored_weight_.assign(cell_count * kDirections, std::pow(std::max(initial, kPheromoneFloor), alpha));
    dirty_.assign(cell_count * kDirections, 0);
    changed_.clear();
  }

  std::size_t cellCount() const { return stored_.size() / kDirections; }
  double alpha() const { return alpha_; }

  double tau(std::size_t cell, int dir) const {
    return std::max(scale_ * stored_[cell * kDirections + dir], kPheromoneFloor);
  }

  // tau^alpha, the pheromone factor of Eq. 8.
  double weight(std::size_t cell, int dir) const {
    return std::max(weight_scale_ * stored_weight_[cell * kDirections + dir], floor_weight_);
  }

  // Largest pheromone leaving a cell (for pictures).
  double strongestFrom(std::size_t cell) const {
    double strongest = 0.0;
    for (int d = 0; d < kDirections; ++d) strongest = std::max(strongest, tau(cell, d));
    return strongest;
  }

  // Sets tau of one edge; its weight follows at the next refreshChanged().
  void set(std::size_t cell, int dir, double value) {
    const std::size_t e = cell * kDirections + dir;
    stored_[e] = value / scale_;
    markChanged(e);
  }

  // Raises tau of one edge to `value` where that is more; its weight follows at the next refreshChanged().
  void raise(std::size_t cell, int dir, double value) {
    const std::size_t e = cell * kDirections + dir;
    if (value / scale_ <= stored_[e]) return;
    stored_[e] = value / scale_;
    markChanged(e);
  }

  // tau <- (1 - rho) tau on every edge.
  void evaporate(double rho) {
    const double keep = 1.0 - rho;
    if (!(keep > 0.0)) {  // rho = 1: everything at the floor
      std::fill(stored_.begin(), stored_.end(), 0.0);
      std::fill(stored_weight_.begin(), stored_weight_.end(), 0.0);
      scale_ = weight_scale_ = 1.0;
      return;
    }
    scale_ *= keep;
    weight_scale_ *= std::pow(keep, alpha_);
    if (std::min(scale_, weight_scale_) < 1e-100) renormalise();
  }

  // tau <- min(max(tau, lo), hi) on every edge (MAACO's bounds); floors and re-weighs as it goes.
  void clamp(double lo, double hi) {
    refreshChanged();
    for (std::size_t e = 0; e < stored_.size(); ++e) {
      const double value = scale_ * stored_[e];
      if (value >= lo && value <= hi) continue;
      stored_[e] = std::min(std::max(value, lo), hi) / scale_;
      reweigh(e);
    }
  }

  // tau += amount on one edge (negative for the penalty of Eq. 24); call refreshChanged() after.
  void deposit(std::size_t cell, int dir, double amount) {
    const std::size_t e = cell * kDirections + dir;
    stored_[e] += amount / scale_;
    markChanged(e);
  }

  // Floors and re-weighs the edges set() or deposit() touched since the last call: one pow() per edge.
  void refreshChanged() {
    for (std::uint32_t e : changed_) reweigh(e);
    changed_.clear();
  }

  // Floors and re-weighs every edge.
  void refreshWeights() {
    for (std::size_t e = 0; e < stored_.size(); ++e) reweigh(e);
    changed_.clear();
  }

 private:
  void markChanged(std::size_t e) {
    if (dirty_[e]) return;
    dirty_[e] = 1;
    changed_.push_back(static_cast<std::uint32_t>(e));
  }

  void reweigh(std::size_t e) {
    stored_[e] = std::max(stored_[e], kPheromoneFloor / scale_);
    stored_weight_[e] = std::pow(stored_[e] * scale_, alpha_) / weight_scale_;
    dirty_[e] = 0;
  }

  // Folds the common scale into the stored values before it underflows.
  void renormalise() {
    for (double& s : stored_) s *= scale_;
    for (double& w : stored_weight_) w *= weight_scale_;
    scale_ = weight_scale_ = 1.0;
  }

  double alpha_ = 1.0;
  double floor_weight_ = 0.0;
  double scale_ = 1.0;         // tau = scale_ * stored_
  double weight_scale_ = 1.0;  // tau^alpha = weight_scale_ * stored_weight_
  std::vector<double> stored_;
  std::vector<double> stored_weight_;
  std::vector<std::uint8_t> dirty_;
  std::vector<std::uint32_t> changed_;
};

}  // namespace eaci
