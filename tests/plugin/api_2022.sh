#!/usr/bin/env bash
# Compiles (no link: there is no MeshLab 2022.02 on bookworm) the plugin against the MeshLab
# 2022.02 plugin API and checks what the objects export: the 2022 interface id and the PyMeshLab
# name. usage: api_2022.sh BUILD_DIR
set -euo pipefail
BUILD=$1
cmake --build "$BUILD" --target filter_hrsr_api_2022
objects=$(find "$BUILD" -path '*filter_hrsr_api_2022.dir*' -name '*.o')
[ -n "$objects" ] || { echo "no object files of filter_hrsr_api_2022"; exit 1; }
passed=0; failed=0
check() { if grep -aq "$2" $objects; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $1"; fi; }
check "the 2022 filter-plugin interface id is exported" "vcg.meshlab.FilterPlugin/1.0"
check "the PyMeshLab name is generate_surface_reconstruction_hrsr" "generate_surface_reconstruction_hrsr"
if grep -aq "vcg.meshlab.MeshFilterInterface" $objects; then
  failed=$((failed + 1)); echo "FAILED: the 2020.09 interface id is exported"
else passed=$((passed + 1)); fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
