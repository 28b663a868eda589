#!/usr/bin/env python3
"""A page's code excerpts stand in its example: each ```cpp block of PAGE, line by line (leading and
trailing blank lines aside), is a run of consecutive lines of one file of FOLDER.

Usage: check_page_excerpts.py PAGE FOLDER
Exits 1 naming each excerpt found in no file, 0 when every one is found.
"""
import os
import re
import sys


def main():
    page, folder = sys.argv[1], sys.argv[2]
    with open(page, encoding="utf-8") as f:
        text = f.read()
    files = {}
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name), encoding="utf-8") as f:
            files[name] = f.read().split("\n")
    excerpts = re.findall(r"```cpp\n(.*?)```", text, re.S)
    missing = 0
    for excerpt in excerpts:
        lines = excerpt.strip("\n").split("\n")
        found = any(lines == body[i:i + len(lines)] for body in files.values() for i in range(len(body)))
        if not found:
            missing += 1
            print(f"{page}: an excerpt found in no file of {folder}:\n{excerpt}")
    print(f"{page}: {len(excerpts)} excerpt(s), {missing} not in {folder}")
    return 1 if missing or not excerpts else 0


if __name__ == "__main__":
    sys.exit(main())
