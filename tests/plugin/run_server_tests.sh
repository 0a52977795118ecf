#!/usr/bin/env bash
# The MeshLab filter under meshlabserver (headless, xvfb): listed, runs on a cloud without normals
# with the same result as the CLI, and fails cleanly (exit != 0, reason in the log, no output) on
# a bad parameter. usage: run_server_tests.sh PLUGIN.so HRSR_EXE SAMPLE.ply
set -u
PLUGIN=$(readlink -f "$1"); HRSR=$(readlink -f "$2"); SAMPLE=$(readlink -f "$3")
HERE=$(cd "$(dirname "$0")" && pwd)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"   # meshlabserver and some filters write temporary files into the current folder
sh "$HERE/make_prefix.sh" "$PLUGIN" "$WORK/prefix"
SERVER="xvfb-run -a $WORK/prefix/bin/meshlabserver"
passed=0; failed=0
check() { if eval "$2"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $1"; fi; }
faces() { sed -n 's/^element face \([0-9]*\).*/\1/p' "$1" | head -1; }
vertices() { sed -n 's/^element vertex \([0-9]*\).*/\1/p' "$1" | head -1; }

$SERVER -d "$WORK/filters.txt" > /dev/null 2>&1
check "the filter is listed" "grep -q 'Surface Reconstruction: HRsR' '$WORK/filters.txt'"

sh "$HERE/hrsr_script.sh" 70 0 > ok.mlx
$SERVER -l "$WORK/log.txt" -i "$SAMPLE" -o "$WORK/mesh.ply" -m vn -s ok.mlx > "$WORK/out.txt" 2>&1
rc=$?
check "an .mlx run succeeds" "[ $rc -eq 0 ] && [ -s '$WORK/mesh.ply' ]"
check "the log has the report summary" "grep -q 'HRsR: .* triangles' '$WORK/log.txt'"
"$HRSR" reconstruct "$SAMPLE" -o "$WORK/cli.ply" -q
check "same faces and vertices as the CLI" \
  "[ '$(faces "$WORK/mesh.ply")' = '$(faces "$WORK/cli.ply")' ] && [ '$(vertices "$WORK/mesh.ply")' = '$(vertices "$WORK/cli.ply")' ] && [ '$(faces "$WORK/cli.ply")' -gt 1000 ]"

sh "$HERE/hrsr_script.sh" 2 0 > bad.mlx
$SERVER -l "$WORK/bad_log.txt" -i "$SAMPLE" -o "$WORK/bad.ply" -s bad.mlx > "$WORK/bad_out.txt" 2>&1
rc=$?
check "a bad parameter fails (not an abort)" "[ $rc -ne 0 ] && [ $rc -ne 134 ] && [ $rc -ne 139 ]"
check "the reason is in the log" "grep -q 'k (neighbours) must be between' '$WORK/bad_log.txt'"
check "nothing is written on failure" "[ ! -e '$WORK/bad.ply' ]"

# Bad input (issue 7 item 6): a filter failure with the core's message in the log, meshlabserver
# exiting normally (no abort or crash signal), no output, the input file untouched.
ascii_ply() { # N "x y z" per line on stdin -> ascii PLY with N vertices
  printf 'ply\nformat ascii 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\nend_header\n' "$1"
  cat
}
printf '0 0 0\n1 0 0\n' | ascii_ply 2 > two.ply
for i in $(seq 50); do echo "nan 0 nan"; done | ascii_ply 50 > nan.ply
for i in $(seq 50); do echo "1 2 3"; done | ascii_ply 50 > same.ply
for i in $(seq 0 9); do for j in $(seq 0 9); do echo "$i $j 0"; done; done | ascii_ply 100 > grid.ply
sh "$HERE/hrsr_script.sh" 70 0 -5 > bad_handles.mlx
bad_case() { # name input script word
  name=$1; input=$2; script=$3; word=$4
  before=$(sha1sum "$input")
  $SERVER -l "$WORK/$name.log" -i "$input" -o "$WORK/$name.out.ply" -s "$script" > "$WORK/$name.txt" 2>&1
  rc=$?
  # 129-159: killed by a signal (134 abort, 139 segmentation fault); meshlabserver fails with 255
  check "$name: the filter fails (not an abort or a crash)" "[ $rc -ne 0 ] && { [ $rc -lt 129 ] || [ $rc -gt 159 ]; }"
  check "$name: the reason is in the log" "grep -q '$word' '$WORK/$name.log'"
  check "$name: nothing is written" "[ ! -e '$WORK/$name.out.ply' ]"
  check "$name: the input is unchanged" "[ '$(sha1sum "$input")' = '$before' ]"
}
bad_case two two.ply ok.mlx "at least 3 are needed"
bad_case nan nan.ply ok.mlx "none of the 50 points has finite coordinates"
bad_case same same.ply ok.mlx "only 1 distinct point"
bad_case handles grid.ply bad_handles.mlx "Handles must be"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
