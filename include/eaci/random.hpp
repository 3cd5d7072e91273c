// Reproducible random numbers (the ants, the simulated wheel encoders and laser): one stream per (seed,
// iteration, ant), so a run gives the same result whatever the number of threads the ants run on.
#pragma once

#include <cmath>
#include <cstdint>

namespace eaci {

// SplitMix64 (Steele, Lea & Flood 2014): tiny, fast, and its output is fully
// specified, unlike std:: distributions, which differ between standard libraries.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t state) : state_(state) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

// A standard normal draw (Box-Muller from two uniforms): the same numbers for a seed on every
// platform, unlike std::normal_distribution (the simulated encoders' and laser's noise).
inline double standardNormal(SplitMix64& random) {
  const double u1 = 1.0 - random.uniform();  // (0, 1], so the log is finite
  const double u2 = random.uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586476925 * u2);
}

// The stream of ant `ant` in iteration `iteration` of a run seeded with `seed`.
inline SplitMix64 antStream(std::uint64_t seed, std::uint64_t iteration, std::uint64_t ant) {
  SplitMix64 mix(seed);
  const std::uint64_t a = mix.next();
  SplitMix64 mix2(a ^ (iteration * 0xD1B54A32D192ED03ULL));
  const std::uint64_t b = mix2.next();
  SplitMix64 mix3(b ^ (ant * 0xABC98388FB8FAC03ULL));
  return SplitMix64(mix3.next());
}

}  // namespace eaci
