#!/usr/bin/env python3
"""Copies the Markdown the manual is built from into OUT/src, with the links a reader of the manual
follows rewritten: the audits to their HTML pages, the guides and the benchmark results to their pages,
figures to the images Doxygen copies, and any other file of the source tree to the file in the
checkout. The sources keep links that work where they are read as files (a checkout, a forge).

  prepare_sources.py --source SOURCE --out OUT
"""
import argparse
import glob
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "tools"))
from atomic_write import write_atomically  # noqa: E402

# Files of the source tree that are pages or images of the manual, by their path in the tree.
PAGES = {
    "generated/AUDIT.md": "audit/parkin2023.html",
    "generated/spinning/AUDIT.md": "audit/spinning_balls.html",
    "generated/shot/AUDIT.md": "audit/shot.html",
    "generated/billiards/kernels.hpp": "namespacebilliards_1_1kernels.html",
    "generated/billiards/spin_kernels.hpp": "namespacebilliards_1_1kernels_1_1spin.html",
    "generated/billiards/shot_kernels.hpp": "namespacebilliards_1_1kernels_1_1shot.html",
    "bench/RESULTS.md": "results.html",
    "CHANGELOG.md": "changelog.html",
    "examples/README.md": "examples_page.html",
    "programs/README.md": "programs_page.html",
}
LINK = re.compile(r"(\]\()([^)\s#]+)(#[^)\s]*)?(\))")


def rewrite(text, page_folder, source, guides):
    """`text` with each relative link of a page in `page_folder` (relative to `source`) rewritten."""

    def target(match):
        path = match.group(2)
        if re.match(r"^[a-z][a-z0-9+.-]*:", path):
            return match.group(0)
        in_tree = os.path.normpath(os.path.join(page_folder, path)).replace(os.sep, "/")
        anchor = match.group(3) or ""
        if in_tree in PAGES:
            new = PAGES[in_tree]
        elif in_tree.startswith("docs/") and in_tree.endswith(".md") and os.path.basename(in_tree) in guides:
            new = os.path.basename(in_tree)
        elif in_tree.endswith((".svg", ".png")):
            new = os.path.basename(in_tree)  # Doxygen's IMAGE_PATH: docs/figures/ and bench/
        else:
            new = "file://" + os.path.join(source, in_tree)
        return match.group(1) + new + anchor + match.group(4)

    in_fence = False
    lines = []
    for line in text.splitlines(keepends=True):
        if line.lstrip().startswith("```"):
            in_fence = not in_fence
        lines.append(line if in_fence else LINK.sub(target, line))
    return "".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    source = os.path.abspath(args.source)
    out = os.path.join(args.out, "src")
    os.makedirs(out, exist_ok=True)
    guides = sorted(os.path.basename(p) for p in glob.glob(os.path.join(source, "docs", "*.md")))
    pages = [("README.md", "README.md"), ("bench/RESULTS.md", "RESULTS.md"), ("CHANGELOG.md", "CHANGELOG.md"),
             ("examples/README.md", "examples.md"), ("programs/README.md", "programs.md")] + [(f"docs/{g}", g) for g in guides]
    for path, name in pages:
        with open(os.path.join(source, path), encoding="utf-8") as f:
            text = f.read()
        if name == "CHANGELOG.md":
            text = re.sub(r"^# Changelog", "# Changelog {#changelog}", text)
        if name == "RESULTS.md":
            text = re.sub(r"^# Benchmark results", "# Benchmark results {#results}", text)
        if name == "examples.md":
            text = re.sub(r"^# examples", "# The examples {#examples_page}", text)
        if name == "programs.md":
            text = re.sub(r"^# programs", "# The programs {#programs_page}", text)
        write_atomically(os.path.join(out, name), rewrite(text, os.path.dirname(path), source, guides))
    return 0


if __name__ == "__main__":
    sys.exit(main())
