#!/usr/bin/env bash
# Issue 20 item 6: HRsR at the defaults on dragon surface samples of growing size, with 1 and 2
# threads: wall time, peak memory (total and per point above the input's 48 bytes a point), the
# time of every phase, the growth per × 4 points, and quality (r_v, boundary edges, pieces, points
# dropped in folds). Samples are made here from ../shared/data/meshes/dragon_vrip.ply (bench_points
# sample: uniform by area, in random order, each with its triangle's normal) and kept in OUT for
# reruns. Per-tile balance (D-42, D-43): for the collapse and the re-expansion, the slowest tile
# over the mean tile, summed over the stretches that end together, and the seconds a phase's tile
# work would take on as many cores as tiles (the slowest tiles) against its total work.
# Usage: bench/scaling.sh [--sizes 200000,800000,3200000,10000000] [--with-20m] [--threads 1,2]
#                         [--hrsr BIN] [--out DIR] [--build DIR]
# (a benchmark, not a test: about 45 min on 2 cores with 10M, 10 min without)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=$ROOT/build
SIZES=200000,800000,3200000,10000000
THREADS=1,2
HRSR=
OUT=$ROOT/build/scaling
WITH_20M=0
while [ $# -gt 0 ]; do
  case $1 in
    --sizes) SIZES=$2; shift 2 ;;
    --with-20m) WITH_20M=1; shift ;;
    --threads) THREADS=$2; shift 2 ;;
    --hrsr) HRSR=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    *) echo "scaling.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
HRSR=${HRSR:-$BUILD/apps/hrsr}
[ "$WITH_20M" = 1 ] && SIZES=$SIZES,20000000
MESH=$ROOT/../shared/data/meshes/dragon_vrip.ply
[ -f "$MESH" ] || { echo "scaling.sh: needs $MESH (../shared/data)" >&2; exit 1; }
[ -x "$HRSR" ] || { echo "scaling.sh: no hrsr binary at $HRSR (build first)" >&2; exit 1; }
mkdir -p "$OUT"
echo "machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.1f GB", $2 / 1048576}' /proc/meminfo);" \
  "binary $HRSR; commit $(git -C "$ROOT" rev-parse --short HEAD); $(date -u +%F)"
for n in ${SIZES//,/ }; do
  cloud=$OUT/dragon_$n.ply
  [ -f "$cloud" ] || "$BUILD/bench/bench_points" sample "$MESH" "$n" "$cloud" > /dev/null
  for t in ${THREADS//,/ }; do
    run=$OUT/run_${n}_t$t
    /usr/bin/time -f "%e %M" -o "$run.time" "$HRSR" reconstruct "$cloud" -o "$run.ply" \
      --threads "$t" --report "$run.json" -q 2> /dev/null || { echo "failed: $n points, $t threads"; continue; }
    rm -f "$run.ply"
    echo "done: $n points, $t threads ($(cut -d' ' -f1 "$run.time") s)"
  done
done
/usr/bin/python3 - "$OUT" "$SIZES" "$THREADS" <<'PY'
import json, os, sys
out, sizes, threads = sys.argv[1], [int(s) for s in sys.argv[2].split(",")], sys.argv[3].split(",")
runs = {}
for n in sizes:
    for t in threads:
        base = f"{out}/run_{n}_t{t}"
        if os.path.exists(base + ".json") and os.path.exists(base + ".time"):
            seconds, kb = open(base + ".time").read().split()
            runs[n, t] = (json.load(open(base + ".json")), float(seconds), int(kb) * 1024)

def balance(r):
    t = r.get("hrsr", {}).get("tile_times")
    if not t or t["collapse"]["tiles"] < 2:
        return "one tile"
    return ", ".join(f"{name} {t[key]['balance']:.2f} ({t[key]['slowest_tile_seconds']:.1f} of"
                     f" {t[key]['work_seconds']:.1f} s)" for name, key in
                     (("collapse", "collapse"), ("re-expansion", "re-expansion")))

def label(n):
    return f"{n / 1e6:g}M" if n >= 1_000_000 else f"{n // 1000}k"

print("\n| points | threads | time (s) | peak (MB) | KB / point above input | r_v | boundary edges"
      " | pieces | dropped in folds | tile balance |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
for (n, t), (r, seconds, peak) in sorted(runs.items()):
    m, p = r["mesh"], r["points"]
    above = (peak - 48 * n) / n / 1024
    print(f"| {label(n)} | {t} | {seconds:.1f} | {peak / 2**20:,.0f} | {above:.2f} |"
          f" {100 * p['vertex_reference_ratio']:.3f} % | {m['boundary_edges']:,} | {m['components']}"
          f" | {p['dropped']['fold']:,} | {balance(r)} |")
for t in threads:
    have = [n for n in sizes if (n, t) in runs]
    if not have:
        continue
    phases = []
    for n in have:
        for ph in runs[n, t][0]["timings"]:
            if ph["phase"] not in phases:
                phases.append(ph["phase"])
    steps = [(a, b) for a, b in zip(have, have[1:]) if b == 4 * a]
    print(f"\nPhases, {t} thread(s), seconds (and × per × 4 points):\n")
    print("| phase | " + " | ".join(label(n) for n in have) + " | "
          + " | ".join(f"× {label(a)} → {label(b)}" for a, b in steps) + " |")
    print("|---|" + "---:|" * (len(have) + len(steps)))
    def seconds_of(n, phase):
        return sum(x["seconds"] for x in runs[n, t][0]["timings"] if x["phase"] == phase)
    for ph in phases + ["total"]:
        row = [sum(x["seconds"] for x in runs[n, t][0]["timings"]) if ph == "total"
               else seconds_of(n, ph) for n in have]
        ratio = [row[have.index(b)] / row[have.index(a)] if row[have.index(a)] > 0 else 0
                 for a, b in steps]
        print(f"| {ph} | " + " | ".join(f"{x:.2f}" for x in row) + " | "
              + " | ".join(f"{x:.1f}" for x in ratio) + " |")
if all(t in threads for t in ("1", "2")):
    print("\nSpeed-up of 2 threads over 1: " + ", ".join(
        f"{label(n)} {runs[n, '1'][1] / runs[n, '2'][1]:.2f}×" for n in sizes
        if (n, "1") in runs and (n, "2") in runs))
PY
