#!/usr/bin/env bash
# Coverage-guided fuzzing of one reader with libFuzzer (nightly Rust, no
# cargo-fuzz needed): fuzz/README.md.
#   fuzz/libfuzzer.sh lcp|scene|friction|world|dat [libFuzzer options]
# e.g. -runs=200000 or -max_total_time=60. Inputs over 1 s are faults
# (-timeout=1); a fault's input lands in fuzz/artifacts/.
set -euo pipefail
reader=${1:?usage: fuzz/libfuzzer.sh lcp|scene|friction|world|dat [libFuzzer options]}
shift
here=$(cd "$(dirname "$0")" && pwd)
target=x86_64-unknown-linux-gnu
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=3 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing"
(cd "$here" && cargo +nightly build --release --target "$target" --bin "$reader")
# The working corpus, which libFuzzer grows: the committed seeds and, for
# dat, the small Siconos files, copied here at run time (fuzz/target is
# not committed, and neither is the conformance data).
work="$here/target/corpus/$reader"
mkdir -p "$work" "$here/artifacts"
cp "$here/corpus/$reader"/* "$work"/
if [ "$reader" = dat ]; then
    conf=${LCPBATCH_CONFORMANCE:-$here/../../shared/conformance}
    for d in "$conf/siconos" "$conf/siconos-fc3d"; do
        [ -d "$d" ] && find "$d" -name '*.dat' -size -9k -exec cp {} "$work"/ \;
    done
fi
exec "$here/target/$target/release/$reader" "$work" -timeout=1 -rss_limit_mb=4096 \
    -artifact_prefix="$here/artifacts/$reader-" -print_final_stats=1 "$@"
