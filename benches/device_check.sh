#!/usr/bin/env bash
# The prepared check for a session lent a hardware GPU (the `device` tool:
# one NVIDIA H100 beside 16 cores, 15 minutes of device time a session, a
# start costing a minute or more). One run, about 6 minutes at most, GPU and
# CPU side by side on the same machine; every command has its own time limit,
# so a slow one costs its limit, not the run.
#
# Here, before the call (the machine cannot build):
#   cargo build --release --bin lcpbatch --example shader_probe
#   mkdir -p .devbin && cp target/release/lcpbatch target/release/examples/shader_probe .devbin/
#   (.gl/: the Vulkan loader debs, as ../.library/device/README.md says; .gl and
#   .devbin are listed in .git/info/exclude)
# The call: command `bash benches/device_check.sh 2>&1 | tee $OUT/log`,
# carry [".gl", ".devbin"], timeout_s 480.
#
# What it prints, in order: the adapter and auto's cost model (`info`); how
# long each resident kernel takes to build and whether the driver takes it
# (examples/shader_probe.rs: a refused kernel loses the device, which falls
# the resident path back to the CPU); resident worlds against the CPU path
# (frictionless 4-box stacks at 10,000 and 100,000 worlds; μ = 0.5 with
# the projected methods); auto's world calibration; the LCP batch families
# (rows printed as each family ends), after every other kernel's build time.
set -uo pipefail
cd "$(dirname "$0")/.."
for f in .gl/*.deb; do dpkg -x "$f" / >/dev/null 2>&1; done
ldconfig
export XDG_RUNTIME_DIR=/tmp LCPBATCH_CACHE_DIR=/tmp/lcpbatch-cache
bin=.devbin/lcpbatch probe=.devbin/shader_probe gen=shaders/generated
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null
echo "CPU threads: $(nproc)"

run() { # LIMIT_S COMMAND...: the command's output less the per-file lines, its status and wall time
  local limit=$1
  shift
  echo "=== $* (limit ${limit} s)"
  local start
  start=$(date +%s%N)
  timeout "$limit" "$@" 2>&1 | grep -v '^wrote\|^  last step\|slowest phase'
  echo "--- rc=${PIPESTATUS[0]} wall=$((($(date +%s%N) - start) / 1000000)) ms"
}

run 20 "$bin" info --gpu-backend vulkan
run 90 "$probe" vulkan "$gen"/world_*_f64.wgsl "$gen/collide_f64.wgsl" "$gen/lemke_f64.wgsl"
sim="$bin simulate --world stack:4 --gpu-backend vulkan"
for backend in gpu cpu; do
  run 60 $sim --friction 0 --worlds 10000 --steps 50 --backend $backend --out /tmp/sim
done
for backend in gpu cpu; do
  run 60 $sim --friction 0 --worlds 100000 --steps 20 --backend $backend --out /tmp/sim
done
for method in pgs apgd; do
  run 40 $sim --friction 0.5 --friction-solver $method --worlds 10000 --steps 50 --backend gpu --out /tmp/sim
done
# The CPU's own best at μ = 0.5 (exact Coulomb, auto) and its APGD; its PGS
# at the default tolerance (1e-12) ran past 30 s here on 10,000 × 50.
run 40 $sim --friction 0.5 --worlds 10000 --steps 50 --backend cpu --out /tmp/sim
run 40 $sim --friction 0.5 --friction-solver apgd --worlds 10000 --steps 50 --backend cpu --out /tmp/sim
run 60 $sim --friction 0 --worlds 10000 --steps 100 --backend auto --out /tmp/sim
# Every other kernel's build time; it may also fill the driver's shader cache,
# so that the bench below times solving, not compiling.
run 60 "$probe" vulkan $(ls "$gen"/*.wgsl | grep -v 'world_.*_f64\|collide_f64\|lemke_f64')
run 150 "$bin" bench --islands 20000 --batch-sizes 100000 --per-n 20 --gpu-backend vulkan --out /tmp/bench
