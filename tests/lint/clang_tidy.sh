#!/usr/bin/env bash
# The clang_tidy test: .clang-tidy on every .cpp of the library, the CLI and the plugin. It
# configures its own compile database without a unity build: a unity build's database names the
# joined units, not the sources, and run-clang-tidy would then check nothing and pass.
# usage: clang_tidy.sh SOURCE_DIR DB_DIR RUN_CLANG_TIDY CLANG_TIDY [cmake -D arguments...]
set -euo pipefail
SOURCE=$1 DB=$2 RUN=$3 TIDY=$4
shift 4
cmake -S "$SOURCE" -B "$DB" -DCMAKE_UNITY_BUILD=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
  -DHRSR_BUILD_APPS=ON -DHRSR_BUILD_TESTS=OFF -DHRSR_BUILD_BENCH=OFF -DHRSR_BUILD_FUZZERS=OFF "$@" >"$DB.configure.log" 2>&1 ||
  { cat "$DB.configure.log" >&2; exit 1; }
# The library and the CLI are always built: each of their sources must be in the database (the
# plugin's only where MeshLab was found, its host program only in the MeshLab roots).
missing=0
while IFS= read -r f; do
  grep -qF "\"file\": \"$f\"" "$DB/compile_commands.json" || { echo "not in the database: $f" >&2; missing=1; }
done < <(find "$SOURCE/vcg_ext" "$SOURCE/apps" -name '*.cpp')
[ "$missing" = 0 ] || exit 1
"$RUN" -quiet -clang-tidy-binary "$TIDY" -p "$DB" "$SOURCE/(vcg_ext|apps|filter_hrsr)/.*[.]cpp$"
