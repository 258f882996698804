#!/usr/bin/env python3
"""Copies committed benchmark tables into the Markdown pages that show them.

A page marks a copy as

    <!-- from data/bench/FILE.md: HEADING -->
    ...the section of FILE.md under "## HEADING", up to the next heading...
    <!-- end -->

or, for the whole file, `<!-- from data/bench/FILE.md -->`.

`splice.py` rewrites every such block from the file; `splice.py --check`
changes nothing and exits 1 naming each block that differs, so a page can
never show numbers the benchmark did not produce. Standard library only.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAGES = ["README.md", "data/stiff/README.md"]
BLOCK = re.compile(r"(<!-- from (data/bench/[\w.-]+\.md)(?:: (.+?))? -->\n)(.*?)(<!-- end -->)", re.S)


def section(path, heading):
    """The lines of `path` under the heading `heading` (any level), to the
    next heading; the whole file without a heading."""
    text = (ROOT / path).read_text(encoding="utf-8")
    if heading is None:
        return text.strip("\n") + "\n"
    lines = text.splitlines(keepends=True)
    start = None
    for i, line in enumerate(lines):
        if start is None and re.fullmatch(r"#+ " + re.escape(heading) + r"\s*", line):
            start = i + 1
        elif start is not None and line.startswith("#"):
            return "".join(lines[start:i]).strip("\n") + "\n"
    if start is None:
        raise SystemExit(f"splice.py: {path} has no heading '{heading}'")
    return "".join(lines[start:]).strip("\n") + "\n"


def main():
    check = "--check" in sys.argv[1:]
    stale = []
    for page in PAGES:
        path = ROOT / page
        text = path.read_text(encoding="utf-8")

        def fill(m):
            body = section(m.group(2), m.group(3))
            if m.group(4) != body:
                stale.append(f"{page}: the copy of {m.group(2)} '{m.group(3) or 'the whole file'}'")
            return m.group(1) + body + m.group(5)

        new = BLOCK.sub(fill, text)
        if not check and new != text:
            path.write_text(new, encoding="utf-8")
    if check and stale:
        print("stale benchmark tables (run data/bench/regenerate.sh):\n  " + "\n  ".join(stale))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
