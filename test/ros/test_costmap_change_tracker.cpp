// The change tracker in a real costmap_2d LayeredCostmap (built when costmap_2d is found): after
// updates by a layer that writes obstacles, take() holds every cell that changed, and the planning
// service told only those rectangles plans round the new obstacles, on the costmap's own cells.
#include <costmap_2d/layered_costmap.h>
#include <gtest/gtest.h>

#include <boost/make_shared.hpp>

#include <utility>
#include <vector>

#include "costmap_change_tracker.hpp"
#include "planning_service.hpp"

namespace eaci_ros {
namespace {

// Writes lethal cells where it is told, reporting the bounds of each new one (as a sensor layer does).
class ObstacleWriter : public costmap_2d::Layer {
 public:
  ObstacleWriter() {
    current_ = true;
    enabled_ = true;
  }
  void add(unsigned mx, unsigned my) { fresh_.emplace_back(mx, my); }
  void updateBounds(double, double, double, double* min_x, double* min_y, double* max_x, double* max_y) override {
    for (const auto& [mx, my] : fresh_) {
      double wx = 0, wy = 0;
      layered_costmap_->getCostmap()->mapToWorld(mx, my, wx, wy);
      *min_x = std::min(*min_x, wx);
      *min_y = std::min(*min_y, wy);
      *max_x = std::max(*max_x, wx);
      *max_y = std::max(*max_y, wy);
      cells_.emplace_back(mx, my);
    }
    fresh_.clear();
  }
  void updateCosts(costmap_2d::Costmap2D& master, int min_i, int min_j, int max_i, int max_j) override {
    for (const auto& [mx, my] : cells_)
      if (int(mx) >= min_i && int(mx) < max_i && int(my) >= min_j && int(my) < max_j)
        master.setCost(mx, my, costmap_2d::LETHAL_OBSTACLE);
  }

 private:
  std::vector<std::pair<unsigned, unsigned>> fresh_, cells_;
};

bool inside(const eaci_service::CostmapChanges& changes, int x, int y) {
  for (const eaci_service::BufferRect& r : changes.rects)
    if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) return true;
  return false;
}

TEST(CostmapChangeTracker, TakeHoldsEveryChangedCellAndThePlanSeesThem) {
  costmap_2d::LayeredCostmap layers("map", false, false);
  layers.resizeMap(60, 40, 1.0, 0.0, 0.0);
  auto writer = boost::make_shared<ObstacleWriter>();
  auto tracker = boost::make_shared<CostmapChangeTracker>();
  writer->initialize(&layers, "writer", nullptr);
  tracker->initialize(&layers, "tracker", nullptr);
  layers.addPlugin(writer);
  layers.addPlugin(tracker);
  layers.updateMap(0, 0, 0);
  EXPECT_FALSE(tracker->take().known);  // never taken before: everything

  eaci_service::PlanningService service(eaci_service::ServiceSettings{}, eaci_service::Logger{});
  eaci::Parameters params = eaci_service::rosDefaultParameters();
  eaci_service::RosPlannerOptions options;
  options.algorithm = eaci::Algorithm::kAStar;
  options.landmarks = 0;
  service.configure(params, options, "");
  costmap_2d::Costmap2D& master = *layers.getCostmap();
  const auto view = [&] {
    eaci_service::CostmapView v;
    v.cells = master.getCharMap();
    v.frame.width = 60;
    v.frame.height = 40;
    v.frame.resolution = 1.0;
    v.frame_id = "map";
    v.order = eaci::RowOrder::kBottomFirst;
    return v;
  };
  eaci_service::PlanRequest request;
  request.start = {2.5, 20.5};
  request.goal = {57.5, 20.5};
  eaci_service::PlanReply reply = service.plan(view(), request, eaci_service::CostmapChanges::unknown());
  ASSERT_TRUE(reply.ok()) << reply.error;

  // A wall across the straight route at x = 30 (rows 10..30), then two updates, then the plan.
  for (unsigned my = 10; my <= 30; ++my) writer->add(30, my);
  layers.updateMap(0, 0, 0);
  writer->add(45, 5);  // a second update elsewhere
  layers.updateMap(0, 0, 0);
  const eaci_service::CostmapChanges changes = tracker->take();
  ASSERT_TRUE(changes.known);
  for (int my = 10; my <= 30; ++my) EXPECT_TRUE(inside(changes, 30, my)) << my;
  EXPECT_TRUE(inside(changes, 45, 5));
  EXPECT_FALSE(inside(changes, 5, 35));  // nothing happened there

  reply = service.plan(view(), request, changes);
  ASSERT_TRUE(reply.ok()) << reply.error;
  for (const eaci::Cell& c : reply.result.path)  // row = 39 - my
    EXPECT_FALSE(c.col == 30 && c.row >= 9 && c.row <= 29) << "through the new wall at row " << c.row;
  EXPECT_EQ(reply.phases.rows_changed, 22u);  // 21 rows of the wall, 1 of the other cell

  EXPECT_TRUE(tracker->take().known);  // nothing since: known, no rectangle
  EXPECT_TRUE(tracker->take().rects.empty());
  layers.resizeMap(61, 40, 1.0, 0.0, 0.0);  // a new size: everything
  EXPECT_FALSE(tracker->take().known);
}

}  // namespace
}  // namespace eaci_ros
