#!/usr/bin/env python3
"""Every relative link and image in the given Markdown files resolves to a file or folder of the
checkout: `[text](path)`, `[text](path#anchor)` and `![alt](path)`, relative to the page. Web
addresses (http:, https:, mailto:) and links within the page (#anchor) are not followed; code spans and
fenced code blocks are skipped. Prints each broken link as FILE:LINE: TARGET; exit status 1 when any.

  check_links.py README.md docs/*.md
"""
import os
import re
import sys

LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
CODE_SPAN = re.compile(r"`[^`]*`")


def links(path):
    in_fence = False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if line.lstrip().startswith("```"):
                in_fence = not in_fence
                continue
            if in_fence:
                continue
            for match in LINK.finditer(CODE_SPAN.sub("", line)):
                yield number, match.group(1)


def main(paths):
    if not paths:
        print("check_links.py: no files given, expected Markdown files", file=sys.stderr)
        return 2
    broken = 0
    checked = 0
    for path in paths:
        folder = os.path.dirname(path)
        for number, target in links(path):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
                continue
            checked += 1
            file_part = target.split("#", 1)[0]
            if not os.path.exists(os.path.normpath(os.path.join(folder, file_part))):
                print(f"{path}:{number}: {target} does not resolve (relative to {folder or '.'})")
                broken += 1
    print(f"{checked} relative links in {len(paths)} files, {broken} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
