#!/usr/bin/env python3
"""Opens the built manual's pages in headless Chromium and checks that the math was typeset.

For each page: Chromium loads it from file:// (no server), runs its scripts with a virtual time
budget long enough for MathJax, and dumps the DOM. The page passes when every formula of its source
(each \\( \\) or \\[ \\] pair) became a MathJax element (a typeset frame per formula, at least
LEAST_FORMULAS of them), no formula failed (no MathJax error element), and the rendered text, with
scripts, styles and code left out, holds no raw TeX (no \\frac, no \\( delimiter). A screenshot of each page
must not be blank: at least 0.5 % of its pixels differ from its most common colour. Every relative
link of a page must lead to a file that was built.

Usage: browser_test.py --chromium PATH --html DIR PAGE[:LEAST_FORMULAS]...
Exit status 0 when every page passes, 1 when one fails, 77 (ctest's skip) when Chromium is missing.
"""

import argparse
import collections
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

TIME_BUDGET_MS = 20000
WORKERS = 2


def chromium(binary, profile, *arguments):
    command = [binary, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
               f"--user-data-dir={profile}", f"--virtual-time-budget={TIME_BUDGET_MS}", *arguments]
    return subprocess.run(command, capture_output=True, timeout=180, check=False)


def formulas_in_source(text):
    text = re.sub(r"<script\b.*?</script>", "", text, flags=re.S)
    return len(re.findall(r"\\\((.*?)\\\)", text, flags=re.S)) + len(re.findall(r"\\\[(.*?)\\\]", text, flags=re.S))


def rendered_text(dom):
    """The text a reader sees, less code (which may quote TeX as TeX)."""
    text = re.sub(r"<(script|style|code|pre)\b.*?</\1>", " ", dom, flags=re.S)
    return re.sub(r"<[^>]+>", " ", text)


def png_pixels(data):
    """The RGB(A) rows of a PNG (8-bit, colour types 2 and 6, as Chromium writes), unfiltered."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    k, idat, width, height, channels = 8, b"", 0, 0, 0
    while k < len(data):
        length, kind = struct.unpack(">I4s", data[k : k + 8])
        body = data[k + 8 : k + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour not in (2, 6):
                raise ValueError(f"PNG of depth {depth}, colour type {colour}: not read here")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        k += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        filter_type = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1 : (y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if filter_type == 1:
                line[x] = (line[x] + a) & 255
            elif filter_type == 2:
                line[x] = (line[x] + b) & 255
            elif filter_type == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif filter_type == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


def not_blank_fraction(png):
    width, height, channels, rows = png_pixels(png)
    counts = collections.Counter()
    for row in rows:
        for x in range(0, width * channels, channels * 4):  # every fourth pixel is plenty
            counts[row[x : x + 3]] += 1
    total = sum(counts.values())
    return 1 - counts.most_common(1)[0][1] / total if total else 0


def check_page(binary, html_dir, page, least, work):
    path = os.path.join(html_dir, page)
    if not os.path.isfile(path):
        return [f"{page}: not built"]
    problems = []
    with open(path, encoding="utf-8") as f:
        source = f.read()
    expected = formulas_in_source(source)
    # Every link within the manual leads to a file that was built.
    for href in sorted(set(re.findall(r'href="([^"#?]+)', source))):
        if re.match(r"[a-z]+:", href):
            continue
        if not os.path.exists(os.path.join(os.path.dirname(path), href)):
            problems.append(f"{page}: a link to {href}, which was not built")
    url = "file://" + os.path.abspath(path)
    # One run of Chromium dumps the DOM and takes the screenshot, both after the time budget.
    shot = os.path.join(work, "shot.png")
    if os.path.exists(shot):
        os.remove(shot)
    dump = chromium(binary, os.path.join(work, "profile"), "--dump-dom", f"--screenshot={shot}",
                    "--window-size=1200,1600", url)
    dom = dump.stdout.decode("utf-8", "replace")
    if dump.returncode != 0 or "<body" not in dom:
        return [f"{page}: Chromium failed (exit {dump.returncode}): {dump.stderr.decode()[-300:]}"]
    frames = len(re.findall(r'id="MathJax-Element-\d+-Frame"', dom))
    errors = len(re.findall(r'class="[^"]*(mjx-merror|MathJax_Error)', dom))
    text = rendered_text(dom)
    raw = [token for token in ("\\frac", "\\(", "\\)", "\\f$") if token in text]
    if expected < least:
        problems.append(f"{page}: {expected} formulas in its source, expected at least {least}")
    if frames != expected:
        problems.append(f"{page}: {frames} typeset MathJax elements for {expected} formulas")
    if errors:
        problems.append(f"{page}: {errors} formulas MathJax could not typeset")
    if raw:
        problems.append(f"{page}: raw TeX left in the rendered text: {', '.join(raw)}")
    if not os.path.isfile(shot):
        problems.append(f"{page}: no screenshot (exit {dump.returncode})")
    else:
        with open(shot, "rb") as f:
            fraction = not_blank_fraction(f.read())
        if fraction < 0.005:
            problems.append(f"{page}: the screenshot is blank ({fraction:.4f} of its pixels differ from the background)")
    status = "ok" if not problems else "FAILED"
    print(f"{page}: {frames} of {expected} formulas typeset, {errors} errors, screenshot checked: {status}")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--html", required=True)
    parser.add_argument("pages", nargs="+")
    args = parser.parse_args()
    binary = shutil.which(args.chromium)
    if binary is None:
        print(f"skipped: Chromium not found ({args.chromium}); install Debian's chromium to run this test")
        return 77
    problems = []
    with tempfile.TemporaryDirectory(prefix="billiards-browser-") as work:
        for spec in args.pages:
            page, _, least = spec.partition(":")
            problems += check_page(binary, args.html, page, int(least or 0), work)
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
