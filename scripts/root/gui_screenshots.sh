#!/bin/sh
# Runs INSIDE a root (scripts/root/screenshots.sh copies it there and installs the plugin first):
# MeshLab's GUI under a private Xvfb, driven by xdotool, captured by ImageMagick's `import`.
# usage: gui_screenshots.sh CLOUD OUT_PREFIX [SECONDS]
#   OUT_PREFIX01_filter_dialog.png  the filter dialog on CLOUD
#   OUT_PREFIX02_hrsr.png           after Apply: the new layer "HRsR mesh", the input hidden
#   OUT_PREFIX03_cloud.png          the same view with the input shown and the mesh hidden
# SECONDS: how long the filter may run (default 10; the view is taken after that).
set -eu
CLOUD=$1 OUT=$2 SECONDS_TO_RUN=${3:-10}
unset QT_QPA_PLATFORM # the GUI draws on the X server, not offscreen
export XDG_RUNTIME_DIR=/tmp/xdg-screenshots
mkdir -p -m 700 "$XDG_RUNTIME_DIR"
Xvfb :77 -screen 0 1280x960x24 -nolisten tcp >/tmp/xvfb.log 2>&1 &
XVFB=$!
MESHLAB=""
trap 'kill $MESHLAB $XVFB 2>/dev/null || true' EXIT
export DISPLAY=:77
sleep 2

meshlab_on() { # FILE SECONDS: the GUI on FILE, its main window sized (there is no window manager)
  [ -z "$MESHLAB" ] || { kill "$MESHLAB"; wait "$MESHLAB" 2>/dev/null || true; }
  meshlab "$1" >/tmp/meshlab.log 2>&1 &
  MESHLAB=$!
  WINDOW=$(timeout 60 xdotool search --sync --onlyvisible --name '^MeshLab' | head -1)
  xdotool windowsize "$WINDOW" 1280 960
  sleep "$2"
}

meshlab_on "$CLOUD" 5
xdotool windowfocus --sync "$WINDOW"
xdotool key ctrl+f; sleep 1 # MeshLab's filter search box
xdotool type --delay 30 "Surface Reconstruction: HRsR"; sleep 1
xdotool key Down Return
DIALOG=$(timeout 30 xdotool search --sync --onlyvisible --name '^Surface Reconstruction: HRsR$' | head -1)
sleep 2
import -window root "${OUT}01_filter_dialog.png"
eval "$(xdotool getwindowgeometry --shell "$DIALOG")" # X Y WIDTH HEIGHT; buttons at the bottom
xdotool mousemove $((X + WIDTH * 3 / 4)) $((Y + HEIGHT - 20)) click 1 # Apply
sleep "$SECONDS_TO_RUN"
xdotool mousemove $((X + WIDTH / 4)) $((Y + HEIGHT - 20)) click 1     # Close
sleep 1
xdotool mousemove 875 111 click 1 # hide layer 0 (the input points): its eye icon
# turn the view round the vertical axis to the scanned (front) side: two drags of a quarter turn
for turn in 1 2; do
  xdotool mousemove 200 480 mousedown 1
  for x in 260 320 380 440 500 560 620; do xdotool mousemove "$x" 480; sleep 0.1; done
  xdotool mouseup 1
done
sleep 2
import -window root "${OUT}02_hrsr.png"
xdotool mousemove 875 111 click 1 # show layer 0 again
xdotool mousemove 875 142 click 1 # hide layer 1 (the mesh)
sleep 2
import -window root "${OUT}03_cloud.png"
