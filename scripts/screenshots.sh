#!/usr/bin/env bash
# Regenerates screenshots/*.png: the MeshLab 2020.09 GUI under a private Xvfb, driven by xdotool,
# captured with ImageMagick's `import`. Needs the build (hrsr, libfilter_hrsr.so) and the packages
# of scripts/setup.sh. Not a test: look at the PNGs after running it.
#   01_filter_dialog.png      the filter dialog (select_dropped ticked) on a cloud with outliers
#   02_dropped_selected.png   after Apply: the mesh layer hidden, the dropped points selected (red)
#                             in the input layer
#   03_hrsr.png               the HRsR mesh of the bunny range scans (../shared/data; else the owl)
#   04_hrsr_ballpivoting_poisson.png  HRsR, Ball Pivoting, Screened Poisson (left to right) on the
#                             same cloud (every 8th bunny point), in one view (meshlab_compare.sh)
# usage: scripts/screenshots.sh [BUILD_DIR]     (SCREENSHOT_CLOUD=cloud.ply: another cloud, with
#        oriented normals, for 03 and 04)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=$(cd "${1:-${HRSR_BUILD_DIR:-$ROOT/build}}" && pwd)
OUT="$ROOT/screenshots"
HRSR="$BUILD/apps/hrsr"
PLUGIN="$BUILD/filter_hrsr/libfilter_hrsr.so"
WORK=$(mktemp -d)
XVFB_PID=""; MESHLAB_PID=""
cleanup() {
  [ -z "$MESHLAB_PID" ] || { kill "$MESHLAB_PID" 2>/dev/null || true; wait "$MESHLAB_PID" 2>/dev/null || true; }
  [ -z "$XVFB_PID" ] || { kill "$XVFB_PID" 2>/dev/null || true; wait "$XVFB_PID" 2>/dev/null || true; }
  rm -rf "$WORK"
}
trap cleanup EXIT
mkdir -p "$OUT"
sh "$ROOT/tests/plugin/make_prefix.sh" "$PLUGIN" "$WORK/prefix"

# A private X server: its display number comes back on fd 3.
exec 3> "$WORK/display"
Xvfb -displayfd 3 -screen 0 1280x960x24 -nolisten tcp > "$WORK/xvfb.log" 2>&1 &
XVFB_PID=$!
exec 3>&-
for _ in $(seq 50); do [ -s "$WORK/display" ] && break; sleep 0.1; done
export DISPLAY=":$(cat "$WORK/display")"
export XDG_RUNTIME_DIR="$WORK/xdg"
mkdir -p -m 700 "$XDG_RUNTIME_DIR"

# Starts the GUI on FILE and waits for its main window (no window manager: size it ourselves).
meshlab_on() {
  stop_meshlab
  "$WORK/prefix/bin/meshlab" "$1" > "$WORK/meshlab.log" 2>&1 &
  MESHLAB_PID=$!
  WINDOW=$(timeout 60 xdotool search --sync --name '^MeshLab [0-9]' | head -1)
  xdotool windowsize "$WINDOW" 1280 960
  sleep "${2:-4}"
}
stop_meshlab() {
  [ -z "$MESHLAB_PID" ] || { kill "$MESHLAB_PID" 2>/dev/null || true; wait "$MESHLAB_PID" 2>/dev/null || true; }
  MESHLAB_PID=""
}
shot() { import -window root "$OUT/$1"; echo "screenshots.sh: $OUT/$1"; }
click() { xdotool mousemove "$1" "$2" click 1; sleep "${3:-1}"; }

DATA="python3 $ROOT/scripts/screenshot_data.py"

# --- 01, 02: the dialog and the dropped points, on the owl with 60 random outliers -----------
$DATA outliers "$ROOT/data/owl_little.ply" "$WORK/owl_outliers.ply" 60
meshlab_on "$WORK/owl_outliers.ply"
xdotool windowfocus --sync "$WINDOW"
xdotool key ctrl+f; sleep 1                          # MeshLab's filter search box
xdotool type --delay 30 "Surface Reconstruction: HRsR"; sleep 1
xdotool key Down Return
DIALOG=$(timeout 30 xdotool search --sync --name '^Surface Reconstruction: HRsR$' | head -1)
sleep 2
# The dialog is docked at the top left; its buttons are at fixed offsets from its bottom.
eval "$(xdotool getwindowgeometry --shell "$DIALOG")"  # X Y WIDTH HEIGHT
click $((X + 26)) $((Y + HEIGHT - 72))               # "Select dropped points"
shot 01_filter_dialog.png
click $((X + WIDTH * 3 / 4)) $((Y + HEIGHT - 23)) 12  # Apply (the owl takes a few seconds)
click $((X + WIDTH / 4)) $((Y + HEIGHT - 23))        # Close
click 888 146                                        # hide layer 1 (HRsR mesh): its eye icon
click 968 114                                        # make layer 0 (the input) current
xdotool mousemove 1117 651 mousedown 1               # larger points: drag the Point Size slider
for x in 1121 1125 1130; do xdotool mousemove "$x" 651; sleep 0.1; done
xdotool mouseup 1; sleep 1
shot 02_dropped_selected.png

# --- 03: HRsR (through the filter) on the bunny range scans, or the owl --------------------------
CLOUD=${SCREENSHOT_CLOUD:-$ROOT/../shared/data/scans/bunny_rangescans_merged_normals.ply}
if [ ! -f "$CLOUD" ]; then
  CLOUD="$WORK/owl_normals.ply"
  "$HRSR" normals "$ROOT/data/owl_little.ply" -o "$CLOUD" -q
fi
sh "$ROOT/tests/plugin/hrsr_script.sh" > "$WORK/hrsr.mlx"
( cd "$WORK" && xvfb-run -a "$WORK/prefix/bin/meshlabserver" -i "$CLOUD" -o "$WORK/hrsr.ply" -m vn \
    -s "$WORK/hrsr.mlx" > "$WORK/hrsr.log" 2>&1 ) || { cat "$WORK/hrsr.log" >&2; exit 1; }
meshlab_on "$WORK/hrsr.ply" 6
shot 03_hrsr.png

# --- 04: HRsR, Ball Pivoting, Screened Poisson side by side (scripts/meshlab_compare.sh) ------
# on every 8th point of a cloud over 100,000 points: Ball Pivoting takes over 25 minutes on the
# whole bunny here
SAME="$CLOUD"
if [ "$(head -c 2000 "$CLOUD" | sed -n 's/^element vertex //p' | head -1)" -gt 100000 ]; then
  SAME="$WORK/subsampled.ply"
  $DATA subsample "$CLOUD" "$SAME" 8
fi
bash "$ROOT/scripts/meshlab_compare.sh" "$SAME" "$WORK/compare" "$PLUGIN"
$DATA side_by_side "$WORK/side_by_side.mlp" "$WORK/compare/hrsr.ply" \
  "$WORK/compare/ball_pivoting.ply" "$WORK/compare/poisson.ply"
meshlab_on "$WORK/side_by_side.mlp" 8
shot 04_hrsr_ballpivoting_poisson.png
stop_meshlab
