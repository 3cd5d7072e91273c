#!/usr/bin/env bash
# Time and memory of one plan against map SIZE at a fixed route, and against ROUTE LENGTH on a
# fixed map (docs/benchmarks.md section 10). Every plan is its own eaci_plan process under
# /usr/bin/time, so the peak RSS is that plan's (map load included); the time is eaci_plan's own
# planning time (map load excluded). Per point the median of RUNS runs.
#
#   scripts/scale_route.sh [OUT_DIR] [RUNS]      (default out/scale_route, 3)
#
# The maps: one rooms map of 1600 x 1600 cells (eaci_bench map --kind rooms --seed 1), and its
# top-left N x N crops for N = 200, 400, 800, 1600, written as MovingAI .map files, so the
# route from (1,1) to the free cell nearest (40,40) is the same in every crop.
#   size:   that route in every crop: A*, EACI threads=1, EACI threads=0 (all cores);
#   length: on the 1600 map from (1,1) to the free cell nearest (d,d), d = 25 .. 1590.
# Prefix with `nice -n 19` on a shared machine.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-out/scale_route}
RUNS=${2:-3}
BIN=build/bin
mkdir -p "$OUT"
"$BIN/eaci_bench" map --kind rooms --size 1600 --seed 1 --resolution 1 --out "$OUT/rooms1600.yaml" >/dev/null

# Crops as MovingAI maps; prints "ROW,COL" of the free cell nearest (d,d) for each d asked.
/usr/bin/python3 - "$OUT" <<'PY'
import sys
out = sys.argv[1]
data = open(f"{out}/rooms1600.pgm", "rb").read()
fields, pos = [], 0
while len(fields) < 4:
    while data[pos:pos + 1].isspace(): pos += 1
    start = pos
    while not data[pos:pos + 1].isspace(): pos += 1
    fields.append(data[start:pos])
w, h = int(fields[1]), int(fields[2])
pix = data[pos + 1:pos + 1 + w * h]
free = lambda r, c: pix[r * w + c] == 254
for n in (200, 400, 800, 1600):
    with open(f"{out}/crop{n}.map", "w") as f:
        f.write(f"type octile\nheight {n}\nwidth {n}\nmap\n")
        for r in range(n):
            f.write("".join("." if free(r, c) else "@" for c in range(n)) + "\n")
def nearest(d):
    for k in range(0, 200):
        for r in range(d - k, d + k + 1):
            for c in range(d - k, d + k + 1):
                if 0 <= r < h and 0 <= c < w and free(r, c): return r, c
with open(f"{out}/goals.txt", "w") as f:
    for d in (40, 25, 50, 100, 200, 400, 800, 1590):
        r, c = nearest(d)
        f.write(f"{d} {r},{c}\n")
PY
goal_for() { awk -v d="$1" '$1 == d { print $2 }' "$OUT/goals.txt"; }

# One plan: prints "time_ms rss_mb length".
plan() {  # MAP GOAL ALGORITHM [--set ...]
  local map=$1 goal=$2 algorithm=$3; shift 3
  local ms length kb
  if /usr/bin/time -f "%M" -o "$OUT/time.txt" "$BIN/eaci_plan" --map "$map" --start 1,1 --goal "$goal" \
    --algorithm "$algorithm" "$@" >"$OUT/plan.txt" 2>&1; then
    length=$(awk '/^grid route:/ { print $4 }' "$OUT/plan.txt")
  else
    length=nan  # no route (exit 3)
  fi
  ms=$(awk '/^time:/ { print $2 }' "$OUT/plan.txt")
  ms=${ms:-nan}
  kb=$(tail -1 "$OUT/time.txt")
  echo "$ms $(awk -v k="$kb" 'BEGIN { printf "%.1f", k / 1024 }') $length"
}

# Median over RUNS plans of each column: prints "time_ms rss_mb length".
median_plan() {
  for _ in $(seq "$RUNS"); do plan "$@"; done | /usr/bin/python3 -c '
import sys, statistics
rows = [list(map(float, l.split())) for l in sys.stdin if l.strip()]
print(" ".join(f"{statistics.median(c):g}" for c in zip(*rows)))'
}

row() {  # LABEL MAP GOAL: one CSV row: A*, EACI 1 thread, EACI all cores
  local a e1 e0
  a=$(median_plan "$2" "$3" astar)
  e1=$(median_plan "$2" "$3" eaci --set threads=1)
  e0=$(median_plan "$2" "$3" eaci --set threads=0)
  read -r a_ms a_mb a_len <<<"$a"
  read -r e1_ms e1_mb e1_len <<<"$e1"
  read -r e0_ms e0_mb _ <<<"$e0"
  echo "$1,$3,$a_len,$a_ms,$a_mb,$e1_len,$e1_ms,$e1_mb,$e0_ms,$e0_mb" | tee -a "$CSV"
}

header="goal_row,goal_col,astar_length,astar_ms,astar_rss_mb,eaci_length,eaci_ms,eaci_rss_mb,eaci_threads0_ms,eaci_threads0_rss_mb"
CSV="$OUT/size.csv"; echo "map_size,$header" | tee "$CSV"
for n in 200 400 800 1600; do row "$n" "$OUT/crop$n.map" "$(goal_for 40)"; done
CSV="$OUT/length.csv"; echo "d,$header" | tee "$CSV"
for d in 25 50 100 200 400 800 1590; do row "$d" "$OUT/crop1600.map" "$(goal_for "$d")"; done
