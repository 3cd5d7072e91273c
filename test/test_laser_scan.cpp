// The simulated laser (include/eaci/robot/laser_scan.hpp): ranges against walls whose distances
// are worked out by hand, no beam through the corner where two blocked cells meet diagonally,
// REP 117's infinities, and the noise's statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "eaci/robot/laser_scan.hpp"

using namespace eaci::robot;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPiTest = 3.14159265358979323846;

// A map of 10 x 10 m in 0.1 m cells, origin (0, 0), blocked where `cells` says (row 0 = top:
// the cell of row r spans y from 10 - 0.1 (r + 1) to 10 - 0.1 r).
struct TestMap {
  eaci::MapFrame frame;
  std::set<std::pair<int, int>> cells;  // (row, col)
  TestMap() {
    frame.width = frame.height = 100;
    frame.resolution = 0.1;
  }
  bool operator()(const eaci::Cell& c) const { return cells.count({c.row, c.col}) > 0; }
  void blockColumn(int col) {
    for (int row = 0; row < 100; ++row) cells.insert({row, col});
  }
};

}  // namespace

// A wall of column 60 (x from 6.0 to 6.1 m); the sensor at (2.05, 5.05).
TEST(LaserScan, ABeamStopsAtTheWallsNearFace) {
  TestMap map;
  map.blockColumn(60);
  const Eigen::Vector2d sensor(2.05, 5.05);
  EXPECT_NEAR(castBeam(map.frame, map, sensor, 0.0, 30.0), 3.95, 1e-9);                         // 6.0 - 2.05
  EXPECT_NEAR(castBeam(map.frame, map, sensor, kPiTest / 4, 30.0), 3.95 * std::sqrt(2.0), 1e-9);  // 45 degrees up
  EXPECT_EQ(castBeam(map.frame, map, sensor, -kPiTest / 3, 30.0), kInf);  // leaves the map at y = 0 first
  EXPECT_EQ(castBeam(map.frame, map, sensor, kPiTest, 30.0), kInf);            // away from the wall, off the map
  EXPECT_EQ(castBeam(map.frame, map, sensor, 0.0, 3.9), kInf);                 // the wall beyond range_max
}

// Two blocked cells meet at a corner only: (row 50, col 51) spans x 5.1-5.2, y 4.9-5.0, and
// (row 49, col 50) x 5.0-5.1, y 5.0-5.1; they touch at (5.1, 5.0). A beam along y = x - 0.1
// crosses between them exactly through that corner (from the free cell below-left of it into
// the free cell above-right): it must hit there, |(5.1, 5.0) - (3.1, 3.0)| = 2 sqrt 2 m away.
TEST(LaserScan, NoBeamSlipsThroughTheCornerOfTwoDiagonalCells) {
  TestMap map;
  map.cells = {{50, 51}, {49, 50}};
  EXPECT_NEAR(castBeam(map.frame, map, Eigen::Vector2d(3.1, 3.0), kPiTest / 4, 30.0), 2.0 * std::sqrt(2.0), 1e-9);
  // Without one of them the corner is open on that side: the beam still touches the other's corner.
  map.cells = {{50, 51}};
  EXPECT_NEAR(castBeam(map.frame, map, Eigen::Vector2d(3.1, 3.0), kPiTest / 4, 30.0), 2.0 * std::sqrt(2.0), 1e-9);
  map.cells.clear();
  EXPECT_EQ(castBeam(map.frame, map, Eigen::Vector2d(3.1, 3.0), kPiTest / 4, 30.0), kInf);
}

// Beam k along the heading + angle_min + k angle_increment; no return within range_max is
// +infinity, a return nearer than range_min (a wall 5 cm ahead, or the sensor inside it) -infinity.
TEST(LaserScan, AScanFollowsRep117AndTheBeamsAngles) {
  TestMap map;
  map.blockColumn(60);
  LaserSpec spec;
  spec.beams = 4;
  spec.angle_min = -kPiTest / 2;
  spec.angle_increment = kPiTest / 2;  // beams at -90, 0, 90 and 180 degrees from the heading
  const std::vector<float> ranges = castScan(map.frame, map, Eigen::Vector2d(5.55, 5.05), kPiTest / 2, spec);
  ASSERT_EQ(ranges.size(), 4u);
  EXPECT_NEAR(ranges[0], 0.45, 1e-6);                       // heading north: -90 degrees is east, 6.0 - 5.55
  EXPECT_EQ(ranges[1], std::numeric_limits<float>::infinity());  // north: off the map at 10 m, no return
  EXPECT_EQ(ranges[2], std::numeric_limits<float>::infinity());  // west: off the map
  EXPECT_EQ(ranges[3], std::numeric_limits<float>::infinity());  // south: off the map
  spec.beams = 1;
  spec.angle_min = 0.0;
  EXPECT_EQ(castScan(map.frame, map, Eigen::Vector2d(5.95, 5.05), 0.0, spec)[0], -std::numeric_limits<float>::infinity())
      << "a wall 0.05 m ahead is nearer than range_min 0.1 m";
  EXPECT_EQ(castScan(map.frame, map, Eigen::Vector2d(6.05, 5.05), 0.0, spec)[0], -std::numeric_limits<float>::infinity())
      << "inside the wall";
}

// 20,000 scans of one beam 3.95 m from a wall: the mean within 0.5 mm of it, the standard
// deviation within 3 % of range_sigma; the same seed gives the same ranges.
TEST(LaserScan, TheNoiseHasTheSpecsStandardDeviation) {
  TestMap map;
  map.blockColumn(60);
  LaserSpec spec;
  spec.beams = 1;
  spec.angle_min = 0.0;
  eaci::SplitMix64 random(spec.seed);
  double sum = 0.0, sum2 = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double r = castScan(map.frame, map, Eigen::Vector2d(2.05, 5.05), 0.0, spec, &random)[0];
    sum += r;
    sum2 += r * r;
  }
  const double mean = sum / n;
  const double sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 3.95, 5e-4);
  EXPECT_NEAR(sd, spec.range_sigma, 0.03 * spec.range_sigma);
  eaci::SplitMix64 a(7), b(7);
  EXPECT_EQ(castScan(map.frame, map, Eigen::Vector2d(2.05, 5.05), 0.0, spec, &a),
            castScan(map.frame, map, Eigen::Vector2d(2.05, 5.05), 0.0, spec, &b));
}

// The paper's M10P by default; a bad value is named.
TEST(LaserScan, TheDefaultsAreTheM10PAndBadValuesAreNamed) {
  const LaserSpec m10p;
  EXPECT_EQ(m10p.range_min, 0.1);
  EXPECT_EQ(m10p.range_max, 30.0);
  EXPECT_NEAR(m10p.angle_increment * 180.0 / kPiTest, 0.22, 1e-12);
  EXPECT_NEAR(m10p.beams * 0.22, 360.0, 0.22);
  EXPECT_EQ(m10p.scan_rate, 12.0);
  EXPECT_EQ(m10p.mount_height, 0.18);
  EXPECT_EQ(validationError(m10p), "");
  LaserSpec bad;
  bad.range_max = 0.05;
  EXPECT_EQ(validationError(bad).rfind("range_max must be", 0), 0u) << validationError(bad);
  bad = LaserSpec{};
  bad.beams = 0;
  EXPECT_EQ(validationError(bad).rfind("beams must be", 0), 0u);
  bad = LaserSpec{};
  bad.range_sigma = -1;
  EXPECT_EQ(validationError(bad).rfind("range_sigma must be", 0), 0u);
  TestMap map;
  EXPECT_THROW(castScan(map.frame, map, Eigen::Vector2d(1, 1), 0.0, bad), std::invalid_argument);
}
