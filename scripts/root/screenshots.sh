#!/usr/bin/env bash
# Screenshots of MeshLab 2025.07's GUI (the sid root; or SUITE) with our filter, under Xvfb inside
# the root. Installs the plugin into the root's MeshLab for the run and removes it again. Needs
# make_root.sh and build_in_root.sh first.
#   screenshots.sh [SUITE]
#     screenshots/<version>_01_filter_dialog.png and <version>_02_hrsr.png: the filter applied in
#     the GUI to the shipped sample
#   screenshots.sh SUITE CLOUD NAME [SECONDS]
#     screenshots/<version>_NAME.png: CLOUD and the mesh the filter made of it (given SECONDS to
#     run, default 60), side by side in the same view, as MeshLab draws them
set -euo pipefail
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
SUITE=${1:-sid}
R="$ROOT/.deps/roots/$SUITE"
VERSION=$(tr . _ < "$R/meshlab-src/ML_VERSION")
WORK=$(mktemp -d "$R/tmp/screenshots.XXXXXX")
IN=/tmp/$(basename "$WORK")
uninstall() {
  bash "$HERE/in_root.sh" "$R" sh -c 'xargs rm -f < /hrsr/build/install_manifest.txt' || true
  rm -rf "$WORK"
}
trap uninstall EXIT
bash "$HERE/in_root.sh" "$R" cmake --install /hrsr/build >/dev/null
cp "$HERE/gui_screenshots.sh" "$WORK/"
if [ $# -ge 3 ]; then
  cp "$2" "$WORK/cloud.${2##*.}"
  bash "$HERE/in_root.sh" "$R" sh "$IN/gui_screenshots.sh" "$IN/cloud.${2##*.}" "$IN/shot_" "${4:-60}"
  # the 3D view of each (without menus and layer panel): the cloud left, the mesh right
  bash "$HERE/in_root.sh" "$R" convert "$IN/shot_03_cloud.png" "$IN/shot_02_hrsr.png" \
    -crop 836x855+0+65 +repage +append "$IN/side_by_side.png"
  cp "$WORK/side_by_side.png" "$ROOT/screenshots/${VERSION}_$3.png"
  echo "screenshots.sh: screenshots/${VERSION}_$3.png"
  exit 0
fi
cp "$ROOT/data/owl_little.ply" "$WORK/owl.ply"
bash "$HERE/in_root.sh" "$R" sh "$IN/gui_screenshots.sh" "$IN/owl.ply" "$IN/shot_"
for shot in 01_filter_dialog 02_hrsr; do
  cp "$WORK/shot_$shot.png" "$ROOT/screenshots/${VERSION}_$shot.png"
  echo "screenshots.sh: screenshots/${VERSION}_$shot.png"
done
