#!/usr/bin/env python3
"""The clang_tidy test: .clang-tidy on every .cpp of the library, the CLI and the plugin.

Reads the build's compile database. A unity build's database names the joined units
(.../CMakeFiles/<target>.dir/Unity/unity_N_cxx.cxx), not the sources: the units of the checked
targets are checked then (clang-tidy reports in the joined sources through .clang-tidy's
HeaderFilterRegex), which parses vcglib and Eigen once per eight files instead of once per file.
Fails unless every source of the library and the CLI is checked, directly or in a unit (the
plugin's only where MeshLab was found, its host program only in the MeshLab roots).

usage: clang_tidy.py SOURCE_DIR BUILD_DIR RUN_CLANG_TIDY CLANG_TIDY [run-clang-tidy arguments...]
"""
import json
import pathlib
import re
import subprocess
import sys

TARGETS = ("hrsr_core", "hrsr_io", "hrsr", "filter_hrsr")


def main():
    source, build, run, tidy = (pathlib.Path(a) for a in sys.argv[1:5])
    source = source.resolve()
    entries = json.loads((build / "compile_commands.json").read_text())
    ours = re.compile(re.escape(str(source)) + r"/(vcg_ext|apps|filter_hrsr)/.*[.]cpp$")
    unit = re.compile(r".*/CMakeFiles/(" + "|".join(TARGETS) +
                      r")[.]dir/Unity/unity_[0-9]+_cxx[.]cxx$")
    checked, covered = set(), set()
    for e in entries:
        f = str(pathlib.Path(e["directory"], e["file"]))
        if ours.match(f):
            checked.add(f)
            covered.add(f)
        elif unit.match(f):
            checked.add(f)
            covered.update(re.findall(r'#include "([^"]+[.]cpp)"', pathlib.Path(f).read_text()))
    sources = sorted(str(p) for d in ("vcg_ext", "apps") for p in (source / d).rglob("*.cpp"))
    missing = [s for s in sources if s not in covered]
    for s in missing:
        print(f"clang_tidy.py: not in the compile database: {s}", file=sys.stderr)
    if missing or not checked:
        return 1
    print(f"clang_tidy.py: {len(checked)} compile commands cover {len(covered)} sources")
    files = "^(" + "|".join(re.escape(f) for f in sorted(checked)) + ")$"
    return subprocess.call([str(run), "-quiet", "-clang-tidy-binary", str(tidy), "-p", str(build),
                            *sys.argv[5:], files])


if __name__ == "__main__":
    sys.exit(main())
