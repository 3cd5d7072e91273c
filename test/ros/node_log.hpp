// The warnings and errors a node logs on /rosout, so that a test can check *why* a request
// failed (nav_msgs/GetPlan answers every failure with the same empty plan). The test's main
// must spin (ros::AsyncSpinner) for the lines to arrive.
#pragma once

#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>

#include <initializer_list>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace eaci_test {

class NodeLog {
 public:
  // `node`: the node's full name, e.g. "/eaci_planner_node".
  explicit NodeLog(std::string node) : node_(std::move(node)) {
    subscriber_ = nh_.subscribe("/rosout", 1000, &NodeLog::onLine, this);
  }

  void clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    lines_.clear();
  }

  // The first WARN-or-worse line of the node that holds every one of `parts` (no parts: any
  // line), waiting up to `timeout_s` for it; "" if none came.
  std::string waitFor(std::initializer_list<std::string> parts, double timeout_s = 5.0) const {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
    do {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const std::string& line : lines_) {
          bool all = true;
          for (const std::string& part : parts) all = all && line.find(part) != std::string::npos;
          if (all) return line;
        }
      }
      ros::WallDuration(0.02).sleep();
    } while (ros::WallTime::now() < deadline);
    return "";
  }

  // Every WARN-or-worse line of the node so far, one a line (for failure messages).
  std::string seen() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::string all;
    for (const std::string& line : lines_) all += "\n  " + line;
    return all.empty() ? " (none)" : all;
  }

 private:
  void onLine(const rosgraph_msgs::Log::ConstPtr& line) {
    if (line->name != node_ || line->level < rosgraph_msgs::Log::WARN) return;
    std::lock_guard<std::mutex> lock(mutex_);
    lines_.push_back(line->msg);
  }

  std::string node_;
  ros::NodeHandle nh_;
  ros::Subscriber subscriber_;
  mutable std::mutex mutex_;
  std::vector<std::string> lines_;
};

}  // namespace eaci_test
