#!/usr/bin/env python3
"""Every citation in the repository resolves inside it (run as the ctest `citations`).

Checked, in the code (vcg_ext/, apps/, filter_hrsr/, fuzz/, bench/, scripts/, .ci/), tests/
(except tests/data/), docs/, the README and data/README.md:

* "§4.6", "§8.3", "§4.1–4.6", "Appendix A.1": a heading of docs/ALGORITHM.md with that number
  ("### 4.6 ...", "## Appendix A ..."); "MESHLAB.md §1.3", "VCGLIB.md §6": a heading of that file
  in docs/. "paper §1.1" is the HRsR paper's own section and is not checked.
* "D-17": a heading of docs/ALGORITHM.md that names the deviation ("### D-17 ...").
* "NAME.md": a file of that name in docs/ or at the root (or the path as written).
* "Issue 7, item 1" in code and tests: a heading "Issue 7" in docs/REQUIREMENTS.md.
* Nothing names the specification folder outside the repository (only test data may live
  outside it).

Usage: check_citations.py [ROOT]   (default: the repository this script is in). Prints one line
per unresolved citation (file:line: what) and exits 1 if there is any.
       check_citations.py --self-test   plants one bad citation of each kind in a temporary tree
and checks that exactly those are reported (the ctest `citations_self_test`).
"""
import os
import re
import sys

SCANNED_DIRS = ["vcg_ext", "apps", "filter_hrsr", "fuzz", "bench", "scripts", "tests", "docs", ".ci"]
SCANNED_ROOT_FILES = ["README.md", "CMakeLists.txt", "data/README.md"]
SKIPPED_DIRS = {".git", ".deps", "__pycache__", os.path.join("tests", "data")}  # seeds, fixtures
TEXT_SUFFIXES = (".h", ".cpp", ".c", ".py", ".sh", ".md", ".txt", ".cmake", ".mlx")
# Issue numbers are looked up only where code and tests cite them; the status notes in docs/
# and the README's history name issues as history, not as requirements.
ISSUE_CITING_DIRS = ("vcg_ext", "apps", "filter_hrsr", "fuzz", "bench", "scripts", "tests", ".ci")

SELF = os.path.basename(__file__)
# Written in two pieces so that this file does not match itself.
FORBIDDEN = "shared" + "/docs"

SECTION = re.compile(
    r"(?:(?P<doc>[A-Z][A-Z_]*)\.md\s*)?§\s?(?P<num>\d+(?:\.\d+)*)"
    r"(?:\s?[–-]\s?(?P<end>\d+(?:\.\d+)*)(?![\d.]*\s*(?:items?|%)))?")
APPENDIX = re.compile(r"Appendix\s+(?P<num>[A-Z](?:\.\d+)*)")
DEVIATION = re.compile(r"(?<![\w-])D-(?P<num>\d+)\b")
MD_FILE = re.compile(r"(?<![\w/.-])(?P<path>(?:[\w.-]+/)*[A-Z][A-Z_]*\.md)\b")
ISSUE = re.compile(r"\b[Ii]ssues?\s+(?P<num>\d+)")

HEADING = re.compile(r"^#{1,6}\s+(?P<text>.*)$")
HEADING_NUMBER = re.compile(r"^(?:§\s?)?(?P<num>\d+(?:\.\d+)*)\b")


def headings(path):
    """Section numbers, appendix ids, deviations and issue ids of a markdown file's headings."""
    sections, appendices, deviations, issues = set(), set(), set(), set()
    if not os.path.isfile(path):
        return sections, appendices, deviations, issues
    in_code = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                in_code = not in_code
            m = None if in_code else HEADING.match(line)
            if not m:
                continue
            text = m.group("text")
            n = HEADING_NUMBER.match(text)
            if n:
                sections.add(n.group("num"))
            a = re.match(r"Appendix\s+(?P<num>[A-Z](?:\.\d+)*)", text)
            if a:
                appendices.add(a.group("num"))
            deviations.update(d.group("num") for d in DEVIATION.finditer(text))
            i = re.match(r"Issue\s+(?P<num>\d+)\b", text)
            if i:
                issues.add(i.group("num"))
    return sections, appendices, deviations, issues


def scanned_files(root):
    for name in SCANNED_ROOT_FILES:
        if os.path.isfile(os.path.join(root, name)):
            yield name
    for top in SCANNED_DIRS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            rel_dir = os.path.relpath(dirpath, root)
            dirnames[:] = sorted(d for d in dirnames
                                 if d not in SKIPPED_DIRS
                                 and os.path.join(rel_dir, d) not in SKIPPED_DIRS)
            for name in sorted(filenames):
                if name == SELF:
                    continue  # its self-test plants bad citations on purpose
                if name.endswith(TEXT_SUFFIXES) or name in ("CMakeLists.txt", "run"):
                    yield os.path.relpath(os.path.join(dirpath, name), root)


def range_end(start, end):
    """'4.1'–'4.6' ends at 4.6; '6'–'8' at 8; '4.1'–'6' (a short form of 4.1–4.6) at 4.6."""
    s, e = start.split("."), end.split(".")
    if len(e) < len(s):
        e = s[: len(s) - len(e)] + e
    return ".".join(e)


def check(root):
    docs = os.path.join(root, "docs")
    algorithm = headings(os.path.join(docs, "ALGORITHM.md"))
    requirements = headings(os.path.join(docs, "REQUIREMENTS.md"))
    doc_sections = {}
    errors = []

    def sections_of(doc):
        if doc not in doc_sections:
            path = os.path.join(docs, doc + ".md")
            doc_sections[doc] = headings(path)[0] if os.path.isfile(path) else None
        return doc_sections[doc]

    for rel in scanned_files(root):
        try:
            with open(os.path.join(root, rel), encoding="utf-8") as f:
                lines = f.readlines()
        except UnicodeDecodeError:
            continue
        is_code = rel.split(os.sep)[0] in ISSUE_CITING_DIRS
        for lineno, line in enumerate(lines, 1):
            where = f"{rel}:{lineno}"
            if FORBIDDEN in line:
                errors.append(f"{where}: refers to {FORBIDDEN} (the repository's docs are in docs/)")
            for m in SECTION.finditer(line):
                if line[: m.start()].rstrip().lower().endswith("paper"):
                    continue  # the paper's own numbering
                doc = m.group("doc") or "ALGORITHM"
                wanted = [m.group("num")]
                if m.group("end"):
                    wanted.append(range_end(m.group("num"), m.group("end")))
                known = algorithm[0] if doc == "ALGORITHM" else sections_of(doc)
                if known is None:
                    errors.append(f"{where}: {doc}.md §{m.group('num')}: no docs/{doc}.md")
                    continue
                for num in wanted:
                    if num not in known:
                        errors.append(f"{where}: §{num} has no heading in docs/{doc}.md")
            for m in APPENDIX.finditer(line):
                if m.group("num") not in algorithm[1] and m.group("num")[0] not in algorithm[1]:
                    errors.append(f"{where}: Appendix {m.group('num')} is not in docs/ALGORITHM.md")
            for m in DEVIATION.finditer(line):
                if m.group("num") not in algorithm[2]:
                    errors.append(f"{where}: D-{m.group('num')} has no heading in docs/ALGORITHM.md")
            for m in MD_FILE.finditer(line):
                path = m.group("path")
                name = os.path.basename(path)
                candidates = [os.path.join(root, rel_dir, path) for rel_dir in ("", "docs")]
                candidates += [os.path.join(root, "docs", name), os.path.join(root, name),
                               os.path.join(root, os.path.dirname(rel), path)]
                if not any(os.path.isfile(c) for c in candidates) and "$" not in line[: m.start()]:
                    errors.append(f"{where}: {path} is not in the repository")
            if is_code:
                for m in ISSUE.finditer(line):
                    if m.group("num") not in requirements[3]:
                        errors.append(
                            f"{where}: issue {m.group('num')} has no heading in docs/REQUIREMENTS.md")
    return errors


def self_test():
    import tempfile
    files = {
        "docs/ALGORITHM.md": "# T\n## 4. Pre\n### 4.6 Split\n### D-1 Frame\n## Appendix A. Code\n"
                             "```\n### 4.7 not a heading: inside a code block\n```\n",
        "docs/REQUIREMENTS.md": "# R\n## Issue 7: robustness\n",
        "docs/MESHLAB.md": "# M\n### 1.3 CMake\n",
        "vcg_ext/good.h": "// §4.6, D-1, Appendix A.1, MESHLAB.md §1.3, Issue 7 item 1, paper §9.9,\n"
                          "// docs/ALGORITHM.md, README.md, 3-D, -DCMAKE_X=1\n",
        "vcg_ext/bad.h": "// §4.7\n// D-2\n// §4.6–4.7\n// ../" + FORBIDDEN + "/x\n"
                         "// VCGLIB.md §6\n// MESHLAB.md §1.4\n// Appendix B\n// NOPE.md\n",
        "tests/bad.cpp": "// Issue 8, item 2\n",
        "README.md": "issue 8 is history here, not a citation\n",
        "tests/data/fixture.h": "// §9.9, D-99: test data is not read\n",
    }
    expected = {
        "vcg_ext/bad.h:1: §4.7 has no heading in docs/ALGORITHM.md",
        "vcg_ext/bad.h:2: D-2 has no heading in docs/ALGORITHM.md",
        "vcg_ext/bad.h:3: §4.7 has no heading in docs/ALGORITHM.md",
        f"vcg_ext/bad.h:4: refers to {FORBIDDEN} (the repository's docs are in docs/)",
        "vcg_ext/bad.h:5: VCGLIB.md §6: no docs/VCGLIB.md",
        "vcg_ext/bad.h:5: VCGLIB.md is not in the repository",
        "vcg_ext/bad.h:6: §1.4 has no heading in docs/MESHLAB.md",
        "vcg_ext/bad.h:7: Appendix B is not in docs/ALGORITHM.md",
        "vcg_ext/bad.h:8: NOPE.md is not in the repository",
        "tests/bad.cpp:1: issue 8 has no heading in docs/REQUIREMENTS.md",
    }
    with tempfile.TemporaryDirectory() as root:
        for rel, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w", encoding="utf-8") as f:
                f.write(text)
        found = set(check(root))
    for e in sorted(expected - found):
        print("self-test: not reported:", e)
    for e in sorted(found - expected):
        print("self-test: reported wrongly:", e)
    ok = found == expected
    print("check_citations self-test:", "ok" if ok else "FAILED")
    return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    root = os.path.abspath(root)
    errors = check(root)
    for e in errors:
        print(e)
    if errors:
        print(f"check_citations: {len(errors)} unresolved citation(s) in {root}")
        return 1
    print(f"check_citations: every citation in {root} resolves")
    return 0


if __name__ == "__main__":
    sys.exit(main())
