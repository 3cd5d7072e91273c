#!/usr/bin/python3
"""Means of the planner's per-phase profile in a move_base log.

The plugin logs one line per plan at DEBUG on ros.eaci_planner.profile
(config/rosconsole_profile.conf; scripts/compare_make_plan.sh --profile); this prints, per log,
the plans counted and the mean milliseconds of each phase (src/service/planning_service.hpp,
PlanPhases), the first plan on the costmap apart:
    /usr/bin/python3 scripts/profile_summary.py out/make_plan/depot.launch.log
"""
import re
import statistics
import sys

LINE = re.compile(r"total ([0-9.]+) ms: wait ([0-9.]+), costmap ([0-9.]+) \(([^)]*)\), start ([0-9.]+), "
                  r"goal ([0-9.]+), search ([0-9.]+), colony ([0-9.]+), smoothing ([0-9.]+)(?:, tolerance ([0-9.]+))?, "
                  r"finish ([0-9.]+), to nav_msgs/Path ([0-9.]+), publishing ([0-9.]+); the call ([0-9.]+) ms")
PHASES = ["costmap", "start", "goal", "search", "colony", "smoothing", "finish", "to Path", "publishing", "the call"]
GROUPS = [3, 5, 6, 7, 8, 9, 11, 12, 13, 14]


def main():
    for path in sys.argv[1:]:
        plans = [m.groups() for m in LINE.finditer(open(path, errors="replace").read())]
        if not plans:
            print("%s: no profile lines (was the profile logger at DEBUG?)" % path)
            continue
        first, rest = plans[0], plans[1:]
        print("%s: first plan %s ms (costmap %s ms, %s)" % (path, first[13], first[2], first[3]))
        if rest:
            means = ["%s %.3f" % (name, statistics.mean(float(p[g - 1] or 0) for p in rest))
                     for name, g in zip(PHASES, GROUPS)]
            print("  %d later plans, mean ms: %s" % (len(rest), ", ".join(means)))


if __name__ == "__main__":
    main()
