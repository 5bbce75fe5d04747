#!/usr/bin/env bash
# Memory-safety and race checks of texsynth.
#
#   scripts/sanitize.sh asan      AddressSanitizer + UBSan build in build-asan/ (gcc),
#                                 the test suite on small sizes
#   scripts/sanitize.sh valgrind  valgrind memcheck (leaks too) on the ops inside the
#                                 uninstrumented gegl tool, build/ (or
#                                 $TEXSYNTH_NATIVE_BUILD)
#   scripts/sanitize.sh tsan      ThreadSanitizer build in build-tsan/ (clang with
#                                 LLVM's libomp and its Archer tool), the 'concurrency' suite
#   scripts/sanitize.sh all       the three in turn (the default)
#
# Each exits non-zero on any sanitizer report, leak or test failure.
#
# These runs look for memory errors, undefined behaviour, leaks and races,
# not for quality: they set TEXSYNTH_TEST_SMALL=1, under which the tests
# run their engines on small sizes and one seed (32^3 solids), reaching the
# same code as the native run in a fraction of the time, and leave quality
# thresholds, which hold only at full size, to the native run
# (meson test -C build).
# SPDX-License-Identifier: LGPL-3.0-or-later
set -euo pipefail

# --wrap CMD...: meson test's wrapper in the ASan run. Our C tests link
# ASan themselves; python3 and the gegl tool do not, so ASan is preloaded
# into them to check our op modules they load (their own leaks at exit
# are not ours: leak checking stays on for the C tests only).
if [ "${1:-}" = "--wrap" ]; then
  shift
  if ldd "$(command -v "$1")" 2>/dev/null | grep -q libasan; then
    # libgomp keeps a thread pool per thread that started a team, never
    # freed when such a (non-OpenMP) thread exits; only these tests have
    # them (the op modules' leaks are checked by the valgrind run).
    case $1 in
      */test-concurrency|*/test-gegl-threads) export ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0" ;;
    esac
    exec "$@"
  fi
  export LD_PRELOAD="$(gcc -print-file-name=libasan.so)"
  export ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0"
  exec "$@"
fi

cd "$(dirname "$0")/.."
root=$PWD

mode=${1:-all}
run_asan() {
  echo "== AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/)"
  [ -f build-asan/build.ninja ] ||
    # gcc's -fsanitize=undefined leaves out float-to-integer overflow,
    # which extreme pixel values can reach: asked for by name.
    meson setup build-asan -Dbuildtype=debugoptimized -Db_sanitize=address,undefined \
      -Db_lundef=false -Db_ndebug=false \
      -Dc_args=-fsanitize=float-cast-overflow -Dc_link_args=-fsanitize=float-cast-overflow
  # meson test builds what the tests it is given by name depend on, not
  # the benchmarks or the GIMP plug-in.
  # Left out as too slow under ASan: 'quality' (16 exemplars synthesised
  # and measured at 256x256, thresholds only) and the texsynth-measure CLI
  # test (its exact nearest-neighbour search); test-metrics covers the
  # measures.
  # Left out as adding no C coverage for their time: ops-babl-paths (the
  # ops-gi runs again under other babl tolerances), test-volume-periodic
  # (volume-slice's code, measured), and the tests that run no C code of
  # ours: the 'layout' suite and i18n-catalogues. GIMP runs its plug-ins (ghostscript's
  # file-ps too) with ASan preloaded and hangs: the 'gimp' suite skips
  # itself under sanitizers, and is left out here for the tests that do not.
  local tests
  tests=$(meson test -C build-asan --list --no-suite quality --no-suite measure --no-suite gimp \
            --no-suite layout 2> /dev/null | sed -n 's|^.* / ||p' |
          grep -Ev '^(ops-babl-paths|test-volume-periodic|i18n-catalogues)$')
  export TEXSYNTH_TEST_SMALL=1
  export ASAN_OPTIONS="abort_on_error=1:halt_on_error=1:detect_leaks=1:fast_unwind_on_malloc=0:detect_stack_use_after_return=1"
  export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
  export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
  # shellcheck disable=SC2086
  meson test -C build-asan --print-errorlogs --timeout-multiplier 4 \
    --wrapper "$root/scripts/sanitize.sh --wrap" $tests
  meson test -C build-asan --print-errorlogs --timeout-multiplier 4 test-metrics
}

# ASan sees the C test programs and the op modules it is preloaded with;
# valgrind is for what it cannot see: the op modules inside the gegl tool
# as it is installed (uninstrumented GEGL, GLib and babl around them), and
# reads of uninitialised memory, which ASan does not track.
run_valgrind() {
  local native=${TEXSYNTH_NATIVE_BUILD:-build}
  echo "== valgrind memcheck ($native/, the ops in the gegl tool)"
  [ -f "$native/build.ninja" ] || meson setup "$native"
  ninja -C "$native"
  local log; log=$(mktemp)
  export OMP_NUM_THREADS=2
  # GEGL loads every module at start-up; ffmpeg's (ff-load, ff-save) pull
  # in libhwy, whose CPU probe runs AVX-512 code valgrind 3.19 cannot
  # decode (SIGILL inside gegl_init on AVX-512 machines). No run uses them.
  local m modules; modules=$(mktemp -d)
  for m in "$(pkg-config --variable=pluginsdir gegl-0.4)"/*; do
    case $(basename "$m") in ff-*) ;; *) ln -s "$m" "$modules/" ;; esac
  done
  export GEGL_PATH="$root/$native/operations:$modules"
  # The ops inside the gegl tool: GEGL and GLib keep some memory until exit,
  # so only leak records with one of our frames count.
  # The volume ops write and read a real file (8^3), then a PNG as a volume.
  for run in "-i examples/brick.png -o $log.png -- texsynth:synthesize width=40 height=32 seed=1" \
             "-i examples/brick.png -o $log.png -- texsynth:tileable seed=1" \
             "-i examples/brick.png -- texsynth:volume-save path=$log.vol size=8 iterations=2" \
             "-o $log.png -- texsynth:volume-load path=$log.vol axis=x index=3" \
             "-o $log.png -- texsynth:volume-load path=$log.png"; do
    echo "-- gegl ${run#*-- }"
    # shellcheck disable=SC2086
    valgrind --quiet --leak-check=full --show-leak-kinds=definite,indirect --log-file="$log" \
      gegl $run 2> /dev/null
    # Loader-time allocations (libgomp's start-up, _dl_init) are not ours.
    if awk '/are (definitely|indirectly) lost/ {block=1; ours=0; loader=0}
            block && /texsynth|op-common|common\// {ours=1}
            block && /_dl_init|dl_open/ {loader=1}
            /^==[0-9]+== $/ {if (block && ours && !loader) bad=1; block=0}
            END {exit !bad}' "$log"; then
      echo "leaks in texsynth code:"; cat "$log"; return 1
    fi
    if grep -E "Invalid (read|write)|uninitialised|Mismatched free" "$log" | grep -q .; then
      if grep -B2 -A25 -E "Invalid (read|write)|uninitialised" "$log" | grep -qE "texsynth|op-common"; then
        echo "memory errors in texsynth code:"; cat "$log"; return 1
      fi
    fi
    echo "   no errors or leaks in texsynth code"
  done
  [ -s "$log.vol" ] || { echo "texsynth:volume-save wrote no $log.vol under valgrind"; return 1; }
  rm -f "$log" "$log.png" "$log.vol"
  rm -rf "$modules"
}

run_tsan() {
  echo "== ThreadSanitizer (build-tsan/, clang, LLVM libomp + Archer)"
  [ -f build-tsan/build.ninja ] ||
    CC=clang meson setup build-tsan -Dbuildtype=debugoptimized -Db_sanitize=thread -Db_lundef=false
  # Named, the tests make meson test build only what they depend on (the
  # engine, the ops and these tests: half of the tree).
  local tests
  tests=$(meson test -C build-tsan --list --suite concurrency 2> /dev/null | sed -n 's|^.* / ||p')
  # Archer tells TSan about OpenMP's barriers and task waits, which it
  # cannot see in an uninstrumented runtime (GCC's libgomp gives false
  # reports; LLVM's libomp with Archer does not).
  local archer=/usr/lib/llvm-14/lib/libarcher.so
  [ -f "$archer" ] || { echo "$archer missing (Debian package libomp-14-dev)"; return 1; }
  # GLib's slice allocator recycles memory between threads in ways TSan
  # cannot see; plain malloc it can.
  # shellcheck disable=SC2086
  TEXSYNTH_TEST_SMALL=1 G_SLICE=always-malloc OMP_TOOL_LIBRARIES=$archer ARCHER_OPTIONS="verbose=1" \
  TSAN_OPTIONS="halt_on_error=1:abort_on_error=1:second_deadlock_stack=1:suppressions=$root/scripts/tsan.supp" \
    meson test -C build-tsan --print-errorlogs --suite concurrency --timeout-multiplier 6 $tests
}

start=$SECONDS
case $mode in
  asan) run_asan ;;
  valgrind) run_valgrind ;;
  tsan) run_tsan ;;
  all) for m in asan valgrind tsan; do
         t=$SECONDS; "run_$m"; echo "sanitize.sh $m: passed in $((SECONDS - t)) s"
       done ;;
  *) echo "usage: $0 [asan|valgrind|tsan|all]" >&2; exit 2 ;;
esac
echo "sanitize.sh $mode: passed in $((SECONDS - start)) s"
