#!/bin/sh
# Siconos' FrictionContact3D solvers on every .dat file of a folder, timed
# around fc3d_driver (benches/siconos_fc3d.c), one thread: the same-machine
# yardstick beside `lcpbatch bench --friction --fc3d-dir DIR --runs N`.
# Needs Debian's libsiconos-numerics-dev (apt-get install
# libsiconos-numerics-dev) and a C compiler; never a test dependency.
#
# Usage: benches/siconos_fc3d.sh DIR [RUNS] [SOLVERS]
#   DIR      e.g. ../shared/conformance/siconos-fc3d-large
#   RUNS     runs of each solver on each file (default 1)
#   SOLVERS  space-separated, of NSN_AC NSGS PROX (default all three; NSN_AC
#            runs ~18 s on KaplasTower and NSGS ~3 s on BoxesStack1)
set -eu
dir=${1:?usage: $0 DIR [RUNS] [SOLVERS]}
runs=${2:-1}
solvers=${3:-NSN_AC NSGS PROX}
here=$(dirname "$0")
bin=${TMPDIR:-/tmp}/siconos_fc3d
cc -O2 -I/usr/include/siconos -I/usr/include/siconos/numerics \
    -o "$bin" "$here/siconos_fc3d.c" -lsiconos_numerics
export OMP_NUM_THREADS=1
for f in "$dir"/*.dat; do
    for s in $solvers; do
        i=0
        while [ "$i" -lt "$runs" ]; do
            "$bin" "$f" "$s"
            i=$((i + 1))
        done
    done
done
