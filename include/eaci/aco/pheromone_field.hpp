// Pheromone on the directed edges of the grid: tau(i, d) for the move from cell i in direction d.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "eaci/grid/moves.hpp"

namespace eaci {

// Pheromone never drops below this, so that Eq. 8 stays defined after the penalty of Eq. 24.
constexpr double kPheromoneFloor = 1e-10;

class PheromoneField {
 public:
  PheromoneField() = default;
  PheromoneField(std::size_t cell_count, double initial, double alpha)
      : alpha_(alpha), tau_(cell_count * kDirections, initial), weight_(cell_count * kDirections) {
    refreshWeights();
  }

  std::size_t cellCount() const { return tau_.size() / kDirections; }
  double alpha() const { return alpha_; }

  double tau(std::size_t cell, int dir) const { return tau_[cell * kDirections + dir]; }
  double& tau(std::size_t cell, int dir) { return tau_[cell * kDirections + dir]; }

  // tau^alpha, the pheromone factor of Eq. 8, cached by refreshWeights().
  double weight(std::size_t cell, int dir) const { return weight_[cell * kDirections + dir]; }

  // Largest pheromone leaving a cell (for pictures).
  double strongestFrom(std::size_t cell) const {
    const auto first = tau_.begin() + static_cast<std::ptrdiff_t>(cell * kDirections);
    return *std::max_element(first, first + kDirections);
  }

  void evaporate(double rho) {
    const double keep = 1.0 - rho;
    for (double& t : tau_) t *= keep;
  }

  void clampToFloor() {
    for (double& t : tau_) t = std::max(t, kPheromoneFloor);
  }

  void refreshWeights() {
    for (std::size_t e = 0; e < tau_.size(); ++e) weight_[e] = std::pow(tau_[e], alpha_);
  }

 private:
  double alpha_ = 1.0;
  std::vector<double> tau_;
  std::vector<double> weight_;
};

}  // namespace eaci
