#!/usr/bin/env bash
# The installed package (README "Public API"): installs the build's hrsr_devel component into a
# temporary prefix, compiles every installed header on its own against that prefix only, builds
# examples/reconstruct with find_package(hrsr) and checks that it writes the same mesh as the CLI.
# Usage: test_package.sh BUILD_DIR SOURCE_DIR CXX_COMPILER [CXX_FLAGS [EXE_LINKER_FLAGS]]
# (the build's flags: the sanitizer build's libraries need them in the example too)
set -euo pipefail
build=$1 src=$2 cxx=$3 cxxflags=${4:-} ldflags=${5:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" --component hrsr_devel >/dev/null
inc=$tmp/prefix/include
headers=$(cd "$inc" && find hrsr -name '*.h' ! -path 'hrsr/vcg/*' | sort)
count=0
for h in $headers; do # the include directories the package exports, nothing else
  echo "#include <$h>" | "$cxx" -std=c++17 -fsyntax-only -I"$inc" -I"$inc/hrsr" -x c++ - ||
    { echo "FAIL: installed $h does not compile on its own" >&2; exit 1; }
  count=$((count + 1))
done
[ "$count" -ge 10 ] || { echo "FAIL: only $count headers installed" >&2; exit 1; }
echo "$count installed headers compile on their own"
cmake -S "$src/examples/reconstruct" -B "$tmp/example" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$cxxflags" \
  -DCMAKE_EXE_LINKER_FLAGS="$ldflags" >/dev/null
cmake --build "$tmp/example" -j2 >/dev/null
lines=$(grep -c . "$src/examples/reconstruct/main.cpp")
echo "example: $lines lines"
out=$("$tmp/example/reconstruct" "$src/data/owl_little.ply" "$tmp/example.ply")
echo "example: $out"
[[ $out =~ ^([0-9]+)\ vertices,\ ([0-9]+)\ triangles,\ genus\ [0-9]+$ ]] ||
  { echo "FAIL: unexpected output" >&2; exit 1; }
vertices=${BASH_REMATCH[1]} triangles=${BASH_REMATCH[2]}
# owl_little: 10,000 points; a closed surface has about twice as many triangles as vertices
if [ "$vertices" -lt 5000 ] || [ "$triangles" -lt $((3 * vertices / 2)) ]; then
  echo "FAIL: implausible counts" >&2
  exit 1
fi
"$build/apps/hrsr" reconstruct "$src/data/owl_little.ply" -o "$tmp/cli.ply" -q
cmp "$tmp/example.ply" "$tmp/cli.ply"
echo "example: the mesh is byte-identical to hrsr reconstruct's"
