#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan, engine without
# OpenMP so runs are deterministic) in build-fuzz/ and runs each for a
# bounded time from its committed seed corpus, printing executions and
# coverage. Exits non-zero if a target finds a crash, leak or timeout; the
# input is saved in build-fuzz/artifacts/ (turn it into a regression test).
#
#   fuzz/run.sh [SECONDS_PER_TARGET]     (default 30, what CI runs)
#   fuzz/run.sh 600                      a longer search, ten minutes a target
#
# The scratch corpus in build-fuzz/ is kept between runs, so each run goes
# on from what the previous ones found.
# SPDX-License-Identifier: LGPL-3.0-or-later
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}

[ -f build-fuzz/build.ninja ] ||
  CC=clang meson setup build-fuzz -Dfuzzing=true -Dopenmp=disabled -Doperations=disabled \
    -Dtests=false -Dbuildtype=debugoptimized -Db_sanitize=address,undefined -Db_lundef=false
ninja -C build-fuzz
mkdir -p build-fuzz/artifacts

export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# fuzz_one TARGET: runs TARGET for $seconds s; non-zero if it found a bug.
fuzz_one() {
  local target=$1 seeds=fuzz/corpus/${1#fuzz-} work=build-fuzz/corpus-${1#fuzz-}
  local log=build-fuzz/$1.log
  mkdir -p "$work"
  # New inputs go to the scratch corpus; the committed seeds stay as they are.
  build-fuzz/fuzz/$target -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2560 \
    -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/$target- \
    "$work" "$seeds" > "$log" 2>&1
}

# The targets are single-threaded: they run side by side, one per core.
targets="fuzz-params fuzz-volume-read"
declare -A pid
for target in $targets; do
  echo "== $target: $seconds s from $(ls "fuzz/corpus/${target#fuzz-}" | wc -l) seeds"
  fuzz_one "$target" &
  pid[$target]=$!
done
status=0
for target in $targets; do
  log=build-fuzz/$target.log
  work=build-fuzz/corpus-${target#fuzz-}
  if ! wait "${pid[$target]}"; then
    status=1
    tail -n 60 "$log"
    echo "$target FAILED: see $log and build-fuzz/artifacts/"
  fi
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  cov=$(grep -oE 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -n 1)
  echo "$target: ${execs:-?} executions, ${cov:-no coverage line}, corpus $(ls "$work" | wc -l) inputs"
done
exit $status
