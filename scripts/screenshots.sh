#!/usr/bin/env bash
# Regenerates screenshots/*.png: the MeshLab 2020.09 GUI under a private Xvfb, driven by xdotool,
# captured with ImageMagick's `import`. Needs the build (hrsr, libfilter_hrsr.so) and the packages
# of scripts/setup.sh. Not a test: look at the PNGs after running it.
#   01_filter_dialog.png      the filter dialog (select_dropped ticked) on a cloud with outliers
#   02_dropped_selected.png   after Apply: the mesh layer hidden, the dropped points selected (red)
#                             in the input layer
#   03_hrsr.png               the HRsR mesh of the bunny range scans (../shared/data; else the owl)
#   04_hrsr_ballpivoting_poisson.png  HRsR, Ball Pivoting, Screened Poisson (left to right) on the
#                             same cloud, in one view (scripts/meshlab_compare.sh)
# usage: scripts/screenshots.sh [BUILD_DIR]
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

# --- 01, 02: the dialog and the dropped points, on the owl with 60 random outliers -----------
python3 - "$ROOT/data/owl_little.ply" "$WORK/owl_outliers.ply" <<'PY'
import random, struct, sys
data = open(sys.argv[1], 'rb').read()
body = data.index(b'end_header\n') + 11
n = int(data[:body].split(b'element vertex ')[1].split()[0])
pts = [struct.unpack_from('<3f', data, body + 12 * i) for i in range(n)]
lo = [min(p[a] for p in pts) for a in range(3)]
hi = [max(p[a] for p in pts) for a in range(3)]
random.seed(5)
extra = [[lo[a] + (hi[a] - lo[a]) * (1.2 * random.random() - 0.1) for a in range(3)] for _ in range(60)]
head = ('ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n'
        'property float y\nproperty float z\nend_header\n' % (n + len(extra))).encode()
open(sys.argv[2], 'wb').write(head + data[body:body + 12 * n] +
                              b''.join(struct.pack('<3f', *q) for q in extra))
PY
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
for _ in 1 2 3; do click 1150 645 0.3; done          # larger points (Point Size slider)
shot 02_dropped_selected.png

# --- 03, 04: HRsR, Ball Pivoting and Screened Poisson on the bunny range scans (or the owl) ----
CLOUD="$ROOT/../shared/data/scans/bunny_rangescans_merged_normals.ply"
if [ ! -f "$CLOUD" ]; then
  CLOUD="$WORK/owl_normals.ply"
  "$HRSR" normals "$ROOT/data/owl_little.ply" -o "$CLOUD" -q
fi
bash "$ROOT/scripts/meshlab_compare.sh" "$CLOUD" "$WORK/compare" "$PLUGIN"
meshlab_on "$WORK/compare/hrsr.ply" 6
shot 03_hrsr.png
# One project with the three meshes side by side (x offsets), so they share one view and light.
python3 - "$WORK/compare" "$WORK/side_by_side.mlp" <<'PY'
import struct, sys
def x_range(path):
    data = open(path, 'rb').read()
    body = data.index(b'end_header\n') + 11
    head = data[:body].decode()
    n = int(head.split('element vertex ')[1].split()[0])
    stride = 4 * head.split('element vertex')[1].split('element')[0].count('property float')
    xs = [struct.unpack_from('<f', data, body + stride * i)[0] for i in range(n)]
    return min(xs), max(xs)
names = ['hrsr', 'ball_pivoting', 'poisson']
ranges = [x_range('%s/%s.ply' % (sys.argv[1], m)) for m in names]
step = 1.1 * max(hi - lo for lo, hi in ranges)
meshes = ''.join(
    ' <MLMesh label="%s" filename="%s/%s.ply" visible="1">\n  <MLMatrix44>\n'
    '1 0 0 %g \n0 1 0 0 \n0 0 1 0 \n0 0 0 1 \n</MLMatrix44>\n </MLMesh>\n'
    % (m, sys.argv[1], m, k * step) for k, m in enumerate(names))
open(sys.argv[2], 'w').write('<!DOCTYPE MeshLabDocument>\n<MeshLabProject>\n <MeshGroup>\n' +
                             meshes + ' </MeshGroup>\n <RasterGroup/>\n</MeshLabProject>\n')
PY
meshlab_on "$WORK/side_by_side.mlp" 8
shot 04_hrsr_ballpivoting_poisson.png
stop_meshlab
