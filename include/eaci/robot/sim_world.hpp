// The world the simulated car drives in and its laser sees: the obstacles of a map (which may
// differ from the map the planner is given) and boxes that map does not hold, one of which may
// move back and forth along a line. Geometry only: the diff_drive_sim node ray-casts its scans
// here (laser_scan.hpp) and reports how near the car's footprint comes to any of it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "eaci/grid/cell.hpp"
#include "eaci/grid/map_frame.hpp"
#include "eaci/robot/diff_drive.hpp"

namespace eaci::robot {

// An axis-aligned box standing on the floor, in the world frame (m).
struct Box {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d size = Eigen::Vector2d::Zero();  // along x and y
};

// A box whose centre goes from `box.centre` to `to` and back, again and again, at `speed` (m/s),
// leaving `box.centre` at time 0. (Its time is the simulation's to give: BoxWalker.)
struct MovingBox {
  Box box;
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  double speed = 0.0;
};

// The one place a Box is checked. Returns "" when valid, else a sentence.
inline std::string validationError(const Box& b) {
  std::ostringstream e;
  if (!b.centre.allFinite()) e << "a box's centre must be two numbers (got " << b.centre.transpose() << ")";
  else if (!b.size.allFinite() || (b.size.array() <= 0).any())
    e << "a box's size must be two numbers > 0 m (got " << b.size.transpose() << ")";
  return e.str();
}

inline std::string validationError(const MovingBox& m) {
  const std::string box = validationError(m.box);
  if (!box.empty()) return box;
  std::ostringstream e;
  if (!m.to.allFinite()) e << "a moving box's end point must be two numbers (got " << m.to.transpose() << ")";
  else if (!std::isfinite(m.speed) || m.speed < 0)
    e << "a moving box's speed must be a number >= 0 m/s (got " << m.speed << ")";
  return e.str();
}

// Where the moving box stands at time t (s, any sign): its centre has gone speed * t along the
// line and back, turning round at either end (the motion repeats every 2 length / speed).
inline Box boxAt(const MovingBox& m, double t) {
  const Eigen::Vector2d line = m.to - m.box.centre;
  const double length = line.norm();
  Box b = m.box;
  if (length == 0.0 || m.speed == 0.0 || !std::isfinite(t)) return b;
  double travelled = std::fmod(m.speed * t, 2.0 * length);
  if (travelled < 0) travelled += 2.0 * length;
  const double along = travelled <= length ? travelled : 2.0 * length - travelled;
  b.centre += line * (along / length);
  return b;
}

// How the moving box walks along its line: its clock (boxAt's t) runs while its next step keeps
// it more than `margin` from the car or takes it no nearer; otherwise the box waits, and after
// `patience` s of waiting it turns round, as a person who finds the way blocked would.
struct BoxWalker {
  double clock = 0.0;      // s
  double direction = 1.0;  // +1: the clock runs forward, -1: back (the box retraces its steps)
  double waited = 0.0;     // s waited since it last moved

  template <class Distance>  // Distance(const Box&) -> m from the car
  void step(const MovingBox& m, double dt, double margin, double patience, const Distance& distance_to_car) {
    if (!(dt > 0)) return;
    const double next = clock + direction * dt;
    const double now_distance = distance_to_car(boxAt(m, clock)), next_distance = distance_to_car(boxAt(m, next));
    if (next_distance > margin || next_distance >= now_distance) {
      clock = next;
      waited = 0.0;
    } else if ((waited += dt) >= patience) {
      direction = -direction;
      waited = 0.0;
    }
  }
};

// The corners of a rectangle of `half_size` at a pose (x forward), or of a box, counter-clockwise.
inline std::array<Eigen::Vector2d, 4> corners(const Pose2& pose, const Eigen::Vector2d& half_size) {
  const Eigen::Matrix2d r = pose.orientation.toRotationMatrix();
  const Eigen::Vector2d h = half_size;
  return {pose.position + r * Eigen::Vector2d(-h.x(), -h.y()), pose.position + r * Eigen::Vector2d(h.x(), -h.y()),
          pose.position + r * Eigen::Vector2d(h.x(), h.y()), pose.position + r * Eigen::Vector2d(-h.x(), h.y())};
}
inline std::array<Eigen::Vector2d, 4> corners(const Box& b) { return corners(Pose2{b.centre, {}}, 0.5 * b.size); }

// The distance between two convex quadrilaterals (corners in order), 0 when they touch or overlap.
inline double quadDistance(const std::array<Eigen::Vector2d, 4>& a, const std::array<Eigen::Vector2d, 4>& b) {
  // Separating axes: if no edge normal of either separates them, they overlap.
  const auto separated = [](const std::array<Eigen::Vector2d, 4>& p, const std::array<Eigen::Vector2d, 4>& q) {
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector2d edge = p[(i + 1) % 4] - p[i];
      const Eigen::Vector2d normal(edge.y(), -edge.x());
      double p_min = normal.dot(p[0]), p_max = p_min, q_min = normal.dot(q[0]), q_max = q_min;
      for (int k = 1; k < 4; ++k) {
        p_min = std::min(p_min, normal.dot(p[k])), p_max = std::max(p_max, normal.dot(p[k]));
        q_min = std::min(q_min, normal.dot(q[k])), q_max = std::max(q_max, normal.dot(q[k]));
      }
      if (p_max < q_min || q_max < p_min) return true;
    }
    return false;
  };
  if (!separated(a, b) && !separated(b, a)) return 0.0;
  const auto point_to_segment = [](const Eigen::Vector2d& p, const Eigen::Vector2d& s, const Eigen::Vector2d& e) {
    const Eigen::Vector2d d = e - s;
    const double t = std::clamp((p - s).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (s + t * d - p).norm();
  };
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k) {
      best = std::min(best, point_to_segment(a[i], b[k], b[(k + 1) % 4]));
      best = std::min(best, point_to_segment(b[i], a[k], a[(k + 1) % 4]));
    }
  return best;
}

// The square of a cell of `frame`, as a Box.
inline Box cellBox(const MapFrame& frame, const Cell& c) {
  return {frame.cellToWorld(c), Eigen::Vector2d::Constant(frame.resolution)};
}

// Whether a box covers a cell of `frame`: the box and the cell's square share interior. A laser
// on the cells sees the whole box, never less. (A cell that only touches the box's edge, within
// rounding, is not covered.)
inline bool covers(const Box& b, const MapFrame& frame, const Cell& c) {
  const Eigen::Vector2d gap = (frame.cellToWorld(c) - b.centre).cwiseAbs() - 0.5 * (b.size.array() + frame.resolution).matrix();
  const double rounding = 1e-9 * frame.resolution;
  return gap.x() < -rounding && gap.y() < -rounding;
}

// The map's obstacles and the boxes. `occupied` holds one byte per cell of `frame`, row-major,
// row 0 = top, non-zero = obstacle; beyond the map is free space.
class SimWorld {
 public:
  SimWorld(MapFrame frame, std::vector<std::uint8_t> occupied, std::vector<Box> boxes = {},
           std::optional<MovingBox> moving = std::nullopt)
      : frame_(std::move(frame)), occupied_(std::move(occupied)), boxes_(std::move(boxes)), moving_(std::move(moving)) {
    if (frame_.width < 0 || frame_.height < 0 || !(frame_.resolution > 0))
      throw std::invalid_argument("world: the map's size must be >= 0 cells and its resolution > 0 m");
    if (occupied_.size() != static_cast<std::size_t>(frame_.width) * static_cast<std::size_t>(frame_.height))
      throw std::invalid_argument("world: the map holds " + std::to_string(occupied_.size()) + " cells, not " +
                                  std::to_string(frame_.width) + " x " + std::to_string(frame_.height));
    for (const Box& b : boxes_) {
      const std::string error = validationError(b);
      if (!error.empty()) throw std::invalid_argument("world: " + error);
    }
    seen_ = occupied_;
    for (const Box& b : boxes_) burnIn(b);
    if (moving_) {
      const std::string error = validationError(*moving_);
      if (!error.empty()) throw std::invalid_argument("world: " + error);
    }
  }

  const MapFrame& frame() const { return frame_; }

  // Every box where it stands at time t (s): the fixed ones, then the moving one.
  std::vector<Box> boxesAt(double t) const {
    std::vector<Box> all = boxes_;
    if (moving_) all.push_back(boxAt(*moving_, t));
    return all;
  }

  // The moving box, if there is one.
  const std::optional<MovingBox>& movingBox() const { return moving_; }
  // Where the moving box stands at time t, if there is one.
  std::optional<Box> movingBoxAt(double t) const { return moving_ ? std::optional<Box>(boxAt(*moving_, t)) : std::nullopt; }

  // The world's obstacles frozen at time t, as laser_scan.hpp's `blocked(Cell)`.
  struct Snapshot {
    const SimWorld* world;
    std::optional<Box> moving;
    bool operator()(const Cell& c) const {
      if (c.row < 0 || c.col < 0 || c.row >= world->frame_.height || c.col >= world->frame_.width) return false;
      if (world->seen_[static_cast<std::size_t>(c.row) * world->frame_.width + c.col] != 0) return true;
      return moving && covers(*moving, world->frame_, c);
    }
  };
  Snapshot at(double t) const { return {this, movingBoxAt(t)}; }

  // The distance (m) from a rectangle of `half_size` at `pose` (the car's footprint) to the nearest
  // obstacle at time t: the map's occupied cells as squares and the boxes as they are; 0 when
  // they touch or overlap, `reach` when nothing is nearer.
  double footprintClearance(const Pose2& pose, const Eigen::Vector2d& half_size, double t, double reach) const {
    if (!pose.position.allFinite()) return 0.0;  // a pose that is not a number touches everything
    const auto footprint = corners(pose, half_size);
    double best = reach;
    for (const Box& b : boxes_) best = std::min(best, quadDistance(footprint, corners(b)));
    if (moving_) best = std::min(best, quadDistance(footprint, corners(boxAt(*moving_, t))));
    const Eigen::Vector2d radius = Eigen::Vector2d::Constant(half_size.norm() + reach + frame_.resolution);
    forEachCellIn(pose.position - radius, pose.position + radius, [&](const Cell& c, std::size_t i) {
      if (occupied_[i] != 0) best = std::min(best, quadDistance(footprint, corners(cellBox(frame_, c))));
    });
    return best;
  }

 private:
  // Calls f(cell, index) for every cell of the map whose square meets the world rectangle
  // low .. high (m).
  template <class F>
  void forEachCellIn(const Eigen::Vector2d& low, const Eigen::Vector2d& high, const F& f) const {
    const Eigen::Vector2d from = ((low - frame_.origin) / frame_.resolution).array().floor();
    const Eigen::Vector2d to = ((high - frame_.origin) / frame_.resolution).array().ceil();
    const int col0 = static_cast<int>(std::clamp(from.x(), 0.0, double(frame_.width)));
    const int col1 = static_cast<int>(std::clamp(to.x(), 0.0, double(frame_.width)));
    const int up0 = static_cast<int>(std::clamp(from.y(), 0.0, double(frame_.height)));
    const int up1 = static_cast<int>(std::clamp(to.y(), 0.0, double(frame_.height)));
    for (int up = up0; up < up1; ++up)
      for (int col = col0; col < col1; ++col) {
        const Cell c{frame_.height - 1 - up, col};
        f(c, static_cast<std::size_t>(c.row) * frame_.width + col);
      }
  }

  // The cells a fixed box covers are obstacles to the laser, as the map's are.
  void burnIn(const Box& b) {
    forEachCellIn(b.centre - 0.5 * b.size, b.centre + 0.5 * b.size, [&](const Cell& c, std::size_t i) {
      if (covers(b, frame_, c)) seen_[i] = 1;
    });
  }

  MapFrame frame_;
  std::vector<std::uint8_t> occupied_;  // the map's obstacles
  std::vector<std::uint8_t> seen_;      // the map's and the fixed boxes' cells: what the laser hits
  std::vector<Box> boxes_;
  std::optional<MovingBox> moving_;
};

}  // namespace eaci::robot
