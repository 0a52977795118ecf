#!/usr/bin/env bash
# Issue 7 item 5, three stages:
#  1. an ASan + UBSan build (GCC, build-asan/) running the unit and end-to-end tests, except the
#     clang-format check, the MeshLab plugin (not built: MeshLab's own code is not instrumented)
#     and the slowest tests, listed in SLOW below;
#  2. the libFuzzer targets of fuzz/ (clang-14, build-fuzz/), fuzzed from tests/data/fuzz/<target>/
#     for $HRSR_FUZZ_SECONDS (default 60) seconds each, the four quick readers (XYZ, OBJ, PTS,
#     PCD: 0.9–1.6 million inputs a minute, where the others run 1k–23k) for half. An input that
#     crashes is copied there as crash-<hash> (commit it: ctest -R FuzzReplay replays it);
#  3. a ThreadSanitizer build (clang-14, build-tsan/) of the core tests, running those that do
#     the same work at several thread counts (the parallel passes of every phase), with LLVM's
#     OpenMP runtime and its archer tool, which tells TSan about OpenMP's barriers (GCC's libgomp
#     is not instrumented; nor is libomp, whose own accesses are ignored). The one suppression
#     (tests/tsan.supp) is libstdc++'s parallel sort.
# Assumes scripts/setup.sh ran. scripts/test.sh calls this (always when CI=true).
# HRSR_SANITIZER_STAGES="asan fuzz tsan" (default) selects the stages, for local runs.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ASAN=${HRSR_ASAN_BUILD_DIR:-$ROOT/build-asan}
FUZZ=${HRSR_FUZZ_BUILD_DIR:-$ROOT/build-fuzz}
FUZZ_SECONDS=${HRSR_FUZZ_SECONDS:-60}
JOBS=$(nproc)
TSAN=${HRSR_TSAN_BUILD_DIR:-$ROOT/build-tsan}
STAGES=${HRSR_SANITIZER_STAGES:-asan fuzz tsan}
# -O1, line tables only and a unity build (see scripts/build.sh): compiling is most of this
# script's time; traces keep file:line.
OPT=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
     -DCMAKE_UNITY_BUILD=ON)
# Not under the sanitizers: no plugin, no benchmark programs (bench/ only measures; compiling its
# CGAL drivers is minutes), no format check, no package install test (it builds a consumer); real
# scans and the large analytic surfaces (minutes under ASan); determinism across threads and the
# cancellation-timing test (they rerun code the other tests cover; the normal build runs them all);
# the three largest clouds run at 1, 2 and 8 threads (120 s of ASan's test time; TSan runs them,
# and the smaller ones across thread counts stay here).
SLOW='clang_format|clang_tidy|meshlab_server|RealScans|Analytic/HrsrSurface|Analytic/RsrSurface'
SLOW+='|Hrsr.VertexCountFallsAsLMinGrows|SameMeshForOneAndTwoThreads|SameResultForOneAndTwoThreads'
SLOW+='|SameBytesForRepeatedRuns|CancellationPointsAreNeverFarApart|TileGroupsGiveTheSameMesh'
SLOW+='|CgalAgreement.ScanReconstructions|^Package$|FaceSplit.TilesOfAStepGiveOneSplitForAnyThreadCount'
SLOW+='|Hrsr.TiledCloudGivesTheSameMeshForAnyThreadCount|Hrsr.NoisyCloudGivesTheSameMeshForAnyThreadCount'
start=$(date +%s)

# 1. ASan + UBSan
if [[ " $STAGES " == *" asan "* ]]; then
SAN="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
cmake -S "$ROOT" -B "$ASAN" "${OPT[@]}" -DHRSR_BUILD_PLUGIN=OFF -DHRSR_BUILD_BENCH=OFF \
  -DCMAKE_CXX_FLAGS="$SAN" -DCMAKE_EXE_LINKER_FLAGS="$SAN" >/dev/null
cmake --build "$ASAN" -j"$JOBS" >/dev/null
built=$(date +%s)
echo "test_sanitizers.sh: ASan/UBSan build took $(( built - start )) s"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
( cd "$ASAN" && ctest --output-on-failure -j"$JOBS" --timeout 900 -E "$SLOW" )
tested=$(date +%s)
echo "test_sanitizers.sh: ASan/UBSan tests took $(( tested - built )) s"
fi
status=0
if [[ " $STAGES " == *" fuzz "* ]]; then
tested=$(date +%s)

# 2. libFuzzer. Warnings are not errors here: the strict build is GCC's.
CC=clang-14 CXX=clang++-14 cmake -S "$ROOT" -B "$FUZZ" "${OPT[@]}" \
  -DHRSR_BUILD_FUZZERS=ON -DHRSR_BUILD_APPS=OFF -DHRSR_BUILD_TESTS=OFF -DHRSR_BUILD_PLUGIN=OFF \
  -DHRSR_WARNINGS_AS_ERRORS=OFF \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined" \
  >/dev/null
# the quick ones first, two at a time as they pair up below
QUICK=(read_xyz read_obj read_pts read_pcd)
TARGETS=("${QUICK[@]}" read_ply read_las check_mesh reconstruct)
cmake --build "$FUZZ" -j"$JOBS" "${TARGETS[@]/#/--target=fuzz_}" >/dev/null
fuzz_built=$(date +%s)
echo "test_sanitizers.sh: fuzz build took $(( fuzz_built - tested )) s"

export ASAN_OPTIONS=detect_leaks=1
fuzz() { # target: fuzz it; on a finding copy the input into tests/data/fuzz/<target>/
  local t=$1 corpus="$FUZZ/corpus/$1" artifacts="$FUZZ/artifacts/$1/" seconds=$FUZZ_SECONDS
  [[ " ${QUICK[*]} " == *" $t "* ]] && seconds=$(( (FUZZ_SECONDS + 1) / 2 ))
  mkdir -p "$corpus" "$artifacts"
  if "$FUZZ/fuzz/fuzz_$t" "$corpus" "$ROOT/tests/data/fuzz/$t" -max_total_time="$seconds" \
       -timeout=20 -rss_limit_mb=2048 -max_len=4096 -artifact_prefix="$artifacts" \
       -print_final_stats=1 >"$FUZZ/$t.log" 2>&1; then
    echo "test_sanitizers.sh: fuzz_$t: clean ($(grep -o 'stat::number_of_executed_units: *[0-9]*' "$FUZZ/$t.log" | grep -o '[0-9]*$') runs)"
  else
    tail -40 "$FUZZ/$t.log" >&2
    for f in "$artifacts"*; do
      [ -f "$f" ] && cp "$f" "$ROOT/tests/data/fuzz/$t/crash-$(sha1sum "$f" | cut -c1-12)"
    done
    echo "test_sanitizers.sh: FAILED: fuzz_$t found a crash, copied to tests/data/fuzz/$t/" >&2
    return 1
  fi
}
for ((i = 0; i < ${#TARGETS[@]}; i += JOBS)); do # as many fuzzers at once as cores
  pids=()
  for t in "${TARGETS[@]:i:JOBS}"; do fuzz "$t" & pids+=($!); done
  for p in "${pids[@]}"; do wait "$p" || status=1; done
done
echo "test_sanitizers.sh: fuzzing took $(( $(date +%s) - fuzz_built )) s"
fi

# 3. ThreadSanitizer on the tests across thread counts (they run 1, 2 and 8 threads themselves),
# but the 600k-point tile groups (about four minutes under TSan; the others cover its passes).
if [[ " $STAGES " == *" tsan "* ]]; then
stage=$(date +%s)
ARCHER="$(llvm-config-14 --libdir)/libarcher.so"
[ -f "$ARCHER" ] || { echo "test_sanitizers.sh: $ARCHER missing (libomp-14-dev)" >&2; exit 1; }
TSAN_FLAGS="-fsanitize=thread -fno-omit-frame-pointer"
CC=clang-14 CXX=clang++-14 cmake -S "$ROOT" -B "$TSAN" "${OPT[@]}" -DHRSR_BUILD_PLUGIN=OFF \
  -DHRSR_BUILD_BENCH=OFF -DHRSR_BUILD_APPS=OFF -DHRSR_WARNINGS_AS_ERRORS=OFF \
  -DCMAKE_CXX_FLAGS="$TSAN_FLAGS" -DCMAKE_EXE_LINKER_FLAGS="$TSAN_FLAGS" >/dev/null
cmake --build "$TSAN" -j"$JOBS" --target test_core >/dev/null
tsan_built=$(date +%s)
echo "test_sanitizers.sh: TSan build took $(( tsan_built - stage )) s"
rm -f "$TSAN"/tsan.log.*
if ! OMP_TOOL_LIBRARIES="$ARCHER" ARCHER_OPTIONS=verbose=1 \
    TSAN_OPTIONS="suppressions=$ROOT/tests/tsan.supp ignore_noninstrumented_modules=1 history_size=7 log_path=$TSAN/tsan.log" \
    "$TSAN/tests/core/test_core" \
    --gtest_filter='*ThreadCount*:*Threads*:*GroupsOfTiles*-*TileGroupsGiveTheSameMesh*' \
    >"$TSAN/tsan_tests.log" 2>&1; then
  tail -30 "$TSAN/tsan_tests.log" >&2
  cat "$TSAN"/tsan.log.* >&2 2>/dev/null || true
  echo "test_sanitizers.sh: FAILED: ThreadSanitizer tests (log: $TSAN/tsan_tests.log)" >&2
  status=1
elif ! grep -q "Archer detected OpenMP application with TSan" "$TSAN/tsan_tests.log"; then
  echo "test_sanitizers.sh: FAILED: archer did not load; TSan would not see OpenMP's barriers" >&2
  status=1
else
  echo "test_sanitizers.sh: TSan: $(grep -o '[0-9]* tests\? from [0-9]* test suites\? ran' \
    "$TSAN/tsan_tests.log") without a race, in $(( $(date +%s) - tsan_built )) s"
fi
fi
echo "test_sanitizers.sh: total $(( $(date +%s) - start )) s"
exit $status
