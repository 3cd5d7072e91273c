#!/usr/bin/env bash
# The core's folders include only their own layer and the layers below it:
#   grid <- search <- aco <- planner (include/eaci/planner.hpp and include/eaci/planner/),
#   parallel/, random.hpp and number_text.hpp: utilities any folder may use (and that use nothing of the core),
#   io/, robot/, path/, metrics/: apart; each may use grid/ and the utilities, never
#   search/, aco/ or planner (nor each other).
# Prints every include that breaks this (file:line: include) and exits 1; exits 0 when none does.
# Usage: scripts/check_layers.sh [REPOSITORY_ROOT]   (default: the repository this script is in)
set -euo pipefail

root=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
core="$root/include/eaci"
[[ -d $core ]] || { echo "check_layers: no $core" >&2; exit 2; }

# The layer of a header, by its path under include/eaci.
layer_of() {
  case $1 in
    parallel/* | random.hpp | number_text.hpp) echo util ;;
    grid/*) echo grid ;;
    search/*) echo search ;;
    aco/*) echo aco ;;
    planner.hpp | planner/*) echo planner ;;
    io/*) echo io ;;
    robot/*) echo robot ;;
    path/*) echo path ;;
    metrics/*) echo metrics ;;
    *) echo unknown ;;
  esac
}

# The layers a layer may include.
allowed() {
  case $1 in
    util) echo "util" ;;
    grid) echo "util grid" ;;
    search) echo "util grid search" ;;
    aco) echo "util grid search aco" ;;
    planner) echo "util grid search aco planner io path metrics" ;;
    io | robot | path | metrics) echo "util grid $1" ;;
    *) echo "" ;;
  esac
}

violations=0
while IFS= read -r file; do
  rel=${file#"$core"/}
  from=$(layer_of "$rel")
  if [[ $from == unknown ]]; then
    echo "include/eaci/$rel: in no layer (add its folder to scripts/check_layers.sh)"
    violations=$((violations + 1))
    continue
  fi
  ok=" $(allowed "$from") "
  while IFS=: read -r line text; do
    target=$(sed -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"eaci\/([^"]+)".*/\1/' <<<"$text")
    to=$(layer_of "$target")
    if [[ $ok != *" $to "* ]]; then
      echo "include/eaci/$rel:$line: $from includes $to: $text"
      violations=$((violations + 1))
    fi
  done < <(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"eaci/' "$file" || true)
done < <(find "$core" -name '*.hpp' | sort)

if ((violations > 0)); then
  echo "check_layers: $violations include(s) against the layers (grid <- search <- aco <- planner; io, robot, path, metrics apart)"
  exit 1
fi
echo "check_layers: every include of include/eaci keeps to the layers"
