// Transition rules: which candidate an ant takes, given each candidate's weight
// tau^alpha * eta^beta (Eq. 8's numerator), from the ant's own random stream.
#pragma once

#include <cmath>

#include "eaci/random.hpp"

namespace eaci {

// Eq. 8 by roulette wheel: the chosen candidate's position. Degenerate weights (all zero or
// overflowing) fall back to a uniform choice.
inline int rouletteChoice(const double* weights, int count, double total, SplitMix64& rng) {
  if (!(total > 0.0) || !std::isfinite(total)) return static_cast<int>(rng.uniform() * count);
  const double ball = rng.uniform() * total;
  double cumulative = 0.0;
  for (int k = 0; k < count; ++k) {
    cumulative += weights[k];
    if (ball < cumulative) return k;
  }
  return count - 1;
}

// The heaviest candidate, the first of equally heavy ones.
inline int heaviestChoice(const double* weights, int count) {
  int best = 0;
  for (int k = 1; k < count; ++k)
    if (weights[k] > weights[best]) best = k;
  return best;
}

// MAACO's q0 schedule, iteration k of K (1-based), k0 = 0.7 K: q0 (K - k) / K before k0; from
// k0 on it rises again from its value there, q0_k0, by (k - k0) / (K - k0) * (q0 - q0_k0) / 2.
constexpr double kMaacoScheduleTurn = 0.7;  // k0 / K
inline double exploitationProbability(int k, int K, double q0) {
  const double k0 = kMaacoScheduleTurn * K;
  if (k < k0) return (K - k) / static_cast<double>(K) * q0;
  const double at_k0 = (K - k0) / K * q0;
  return at_k0 + (k - k0) / (K - k0) * (q0 - at_k0) / 2.0;
}

// Classic ACO and EACI: Eq. 8 by roulette wheel, the same in every iteration.
struct RouletteTransition {
  void beginIteration(int /*k*/, int /*K*/) {}
  int operator()(const double* weights, int count, double total, SplitMix64& rng) const {
    return rouletteChoice(weights, count, total, rng);
  }
};

// MAACO: with probability q0 (exploitationProbability of the iteration) the heaviest
// candidate, else the roulette wheel. One draw decides, a second spins the wheel.
struct PseudoRandomTransition {
  double q0_initial = 0.5;
  double q0 = 0.5;  // this iteration's

  void beginIteration(int k, int K) { q0 = exploitationProbability(k, K, q0_initial); }
  int operator()(const double* weights, int count, double total, SplitMix64& rng) const {
    if (rng.uniform() <= q0) return heaviestChoice(weights, count);
    return rouletteChoice(weights, count, total, rng);
  }
};

}  // namespace eaci
