#!/usr/bin/env bash
# Builds eaci_bench (Release, no ROS, into build/bench/), runs the studies into out/bench/ (each
# appends its records to out/bench/<study>.jsonl), then writes docs/benchmarks.md's tables and
# docs/figures/ from the records with scripts/bench_report.py.
#   paper    - the paper's Tables 1-3 on its maps, 20 seeds, MAACO and its choices (about 40 s)
#   sweep    - Figs 11-14 parameter studies and classic ACO's rho/tau0           (about 2 min)
#   front    - length against total corner angle on the paper's maps (issue #30)  (about 1 s)
#   scale    - generated maps 50..800 cells, time, memory, gap to A*             (several min)
#   deadline - 800 x 800 maps, wall time against max_planning_time              (about 1 min)
#   costs    - inflated cost maps (the lab, generated 100..800): cost gap to A*  (several min)
#   scen     - the hand-made MovingAI scenario test/data/movingai/wall.scen      (a second)
#   report   - the tables and figures of every study whose records are there
# Usage: scripts/bench.sh [paper|sweep|front|scale|deadline|costs|scen|report ...]   (default: all, then report)
# One study and its tables alone: scripts/bench.sh paper report
# Maps are read from ${EACI_MAPS_DIR:-maps/paper}. Timings are only as good as the machine is
# quiet: each record keeps the load average at the start of its command.
set -euo pipefail
cd "$(dirname "$0")/.."

maps=${EACI_MAPS_DIR:-maps/paper}
out=out/bench
bench=build/bench/bin/eaci_bench
steps=("$@")
[ ${#steps[@]} -gt 0 ] || steps=(paper sweep front scale deadline costs scen report)

EACI_WITH_ROS=OFF scripts/install_deps.sh
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DEACI_WITH_ROS=OFF -DEACI_BUILD_TESTS=OFF >/dev/null
cmake --build build/bench -j"$(nproc)" --target eaci_bench

load=$(cut -d' ' -f1 /proc/loadavg)
if awk -v l="$load" 'BEGIN { exit !(l > 0.5) }'; then
  echo "bench.sh: note: load average is $load; other work on this machine will slow the timings" >&2
fi

mkdir -p "$out"
for step in "${steps[@]}"; do
  case "$step" in
    paper) "$bench" paper --maps "$maps" --runs 20 --threads 1 --out "$out" ;;
    sweep) "$bench" sweep --maps "$maps" --runs 20 --out "$out" ;;
    front) "$bench" front --maps "$maps" --runs 20 --threads 1 --out "$out" ;;
    scale) "$bench" scale --sizes 50,100,200,400,800 --out "$out" ;;
    deadline) "$bench" deadline --sizes 800 --runs 3 --out "$out" ;;
    costs) "$bench" costs --lab-map maps/lab.yaml --sizes 100,200,400,800 --out "$out" ;;
    scen) "$bench" scen test/data/movingai/wall.scen --seeds 3 --out "$out" ;;
    report) /usr/bin/python3 scripts/bench_report.py --records "$out" ;;
    *) echo "bench.sh: unknown step '$step' (paper, sweep, front, scale, deadline, costs, scen, report)" >&2; exit 2 ;;
  esac
done
