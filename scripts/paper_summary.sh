#!/usr/bin/env bash
# Averages of 20 eaci_plan runs (seeds 1-20) on one paper map, corner cutting allowed.
# Usage: scripts/paper_summary.sh MAP_FILE START_CELL GOAL_CELL [extra eaci_plan options]
#   e.g. scripts/paper_summary.sh paper-50x50.txt 2451 50 --set island_strategy=paper
# Maps are read from ${EACI_MAPS_DIR:-maps/paper}. Needs build/bin/eaci_plan.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 3 ] || { sed -n '2,5p' "$0" >&2; exit 2; }
map=$1 start=$2 goal=$3
shift 3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for seed in $(seq 1 20); do
  build/bin/eaci_plan --map "${EACI_MAPS_DIR:-maps/paper}/$map" --start-cell "$start" --goal-cell "$goal" \
    --set allow_corner_cutting=true --seed "$seed" --json "$dir/$seed.json" --quiet "$@" >/dev/null
done
/usr/bin/python3 - "$dir" <<'PY'
import json, sys
runs = [json.load(open(f"{sys.argv[1]}/{s}.json")) for s in range(1, 21)]
mean = lambda key: sum(r[key] for r in runs) / len(runs)
print(f"length avg {mean('length'):.4f} best {min(r['length'] for r in runs):.4f} | "
      f"iterations {mean('iterations_to_converge'):.2f} | lost ants {mean('lost_ants_total'):.2f} | "
      f"turn of the runs (deg) {sorted(set(r['total_turn_deg'] for r in runs))}")
PY
