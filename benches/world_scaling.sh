#!/usr/bin/env bash
# How a world step's cost grows with the number of worlds and with the bodies
# per world: `lcpbatch simulate` over a grid of standard worlds, one line of
# a Markdown table per run (world-steps per wall second and per CPU second of
# the process, and the step's phases as `simulate` prints them).
#
#   benches/world_scaling.sh [LCPBATCH_BINARY] > table.md
#
# The binary defaults to target/release/lcpbatch (`cargo build --release`).
# Each run's steps are chosen so that it takes about a second or more on the
# 2-core development machine; the first steps of a run (cold starts, the
# stacks settling) are included, as a user stepping that many steps sees them.
set -euo pipefail
bin="${1:-target/release/lcpbatch}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

run() { # KIND WORLDS STEPS FRICTION
  local kind=$1 worlds=$2 steps=$3 mu=$4
  local log="$out/log" times="$out/time"
  /usr/bin/time -f "%U %S %e" -o "$times" \
    "$bin" simulate --backend cpu --world "$kind" --worlds "$worlds" --steps "$steps" \
    --friction "$mu" --out "$out/sim" >"$log" 2>&1
  read -r user sys wall <"$times"
  local rate phases
  rate=$(awk '/world-steps\/s/ {print $(NF-1)}' "$log")
  phases=$(sed -n 's/^ *\([a-zA-Z+ ]*\): [0-9.]* s (\([0-9.]*%\))$/\1 \2/p' "$log" |
    grep -v 'assembly+solve' | paste -sd ',' | sed 's/,/, /g')
  local cpu_rate
  cpu_rate=$(awk -v w="$worlds" -v s="$steps" -v u="$user" -v y="$sys" \
    'BEGIN { printf "%.0f", w * s / (u + y) }')
  printf '| `%s` | %s | %s | %s | %s | %s | %s |\n' \
    "$kind" "$mu" "$worlds" "$steps" "$rate" "$cpu_rate" "$phases"
}

echo "| world | μ | worlds | steps | world-steps/s (wall) | per CPU-second | phases (share of the step) |"
echo "|---|---|---:|---:|---:|---:|---|"
# Worlds: 1 to 100,000 of a 4-box stack, frictionless and with friction.
for spec in "1 20000" "10 5000" "100 1000" "1000 200" "10000 20" "100000 3"; do
  run stack:4 $spec 0
done
for spec in "1 2000" "10 500" "100 100" "1000 30" "10000 5" "100000 2"; do
  run stack:4 $spec 0.5
done
# Bodies per world: 1,000 worlds of taller stacks and of more spheres.
for h in 2 8 16; do run "stack:$h" 1000 50 0; done
for n in 8 32 128; do run "spheres:$n" 1000 50 0; done
for h in 2 8; do run "stack:$h" 1000 20 0.5; done
