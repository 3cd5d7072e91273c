#!/usr/bin/env bash
# Builds eaci_bench (Release, no ROS, into build/bench/) and runs the four benchmarks into
# out/bench/, then draws the figures into docs/figures/.
#   paper  - the paper's Tables 1-3 on its maps, 20 seeds          (about 10 s)
#   sweep  - Figs 11-14 parameter studies and classic ACO's rho/tau0 (about 1-2 min)
#   scale  - generated maps 50..800 cells, time, memory, gap to A*  (about 1-2 min)
#   deadline - 800 x 800 maps, wall time against max_planning_time  (about 30 s)
#   costs  - inflated cost maps (the lab, generated 100..800): cost gap to A*, smoothing (a few min)
# Usage: scripts/bench.sh [paper|sweep|scale|deadline|costs|plot ...]   (default: all of them)
# Maps are read from ${EACI_MAPS_DIR:-maps/paper}. Timings are only as good as the
# machine is quiet: the reports record the load average at the start of each run.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:$PATH   # Debian's python3 (matplotlib, numpy), not a pyenv shim

maps=${EACI_MAPS_DIR:-maps/paper}
out=out/bench
figures=docs/figures
bench=build/bench/bin/eaci_bench
steps=("$@")
[ ${#steps[@]} -gt 0 ] || steps=(paper sweep scale deadline costs plot)

EACI_WITH_ROS=OFF scripts/install_deps.sh python3-matplotlib python3-numpy
cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DEACI_WITH_ROS=OFF -DEACI_BUILD_TESTS=OFF >/dev/null
cmake --build build/bench -j"$(nproc)" --target eaci_bench

load=$(cut -d' ' -f1 /proc/loadavg)
if awk -v l="$load" 'BEGIN { exit !(l > 0.5) }'; then
  echo "bench.sh: note: load average is $load; other work on this machine will slow the timings" >&2
fi

mkdir -p "$out" "$figures"
for step in "${steps[@]}"; do
  case "$step" in
    paper) "$bench" paper --maps "$maps" --runs 20 --threads 1 --out "$out" ;;
    sweep) "$bench" sweep --maps "$maps" --runs 20 --out "$out" ;;
    scale) "$bench" scale --sizes 50,100,200,400,800 --out "$out" ;;
    deadline) "$bench" deadline --sizes 800 --runs 3 --out "$out" ;;
    costs) "$bench" costs --lab-map maps/lab.yaml --sizes 100,200,400,800 --out "$out" ;;
    plot)
      results=()
      for kind in paper sweep scale costs; do [ -f "$out/$kind.json" ] && results+=("$out/$kind.json"); done
      /usr/bin/python3 scripts/plot_benchmarks.py "${results[@]}" "$figures" >/dev/null
      echo "figures in $figures/" ;;
    *) echo "bench.sh: unknown step '$step' (paper, sweep, scale, deadline, costs, plot)" >&2; exit 2 ;;
  esac
done

echo "Markdown tables:"
for kind in paper sweep scale deadline costs; do [ -f "$out/$kind.md" ] && echo "  $out/$kind.md"; done
echo "(JSON and CSV beside them; docs/benchmarks.md quotes them)"
