#!/usr/bin/env python3
"""No function over a length: lists each C++ function (or lambda) body longer than --most lines.

Usage: check_function_lengths.py --most N [--most-class M] FILE...

With --most-class, also each class or struct body longer than M lines (its head `class Name …` or
`struct Name …`).

A body is the text between a '{' whose head (what stands since the last ';', '{' or '}') ends in a
parameter list — `name(…)`, `name(…) const`, `noexcept`, `-> type`, or a lambda's `[…](…)` — and its
matching '}'; strings, characters and comments are passed over. Control statements (if, for, while,
switch, catch) are not functions. Exits 1 listing each one too long, 0 when there is none.
"""
import argparse
import re
import sys

CONTROL = re.compile(r"\b(if|for|while|switch|catch|do|else)\s*(constexpr\s*)?\(?[^()]*(\(.*\))?\s*$", re.S)
CLASS = re.compile(r"(^|[\s;{}>])(class|struct)\s+\w+[^;(){}]*$", re.S)
FUNCTION = re.compile(r"\)\s*(const\s*)?(noexcept\s*)?(override\s*)?(->\s*[\w:<>,\s*&]+)?\s*$", re.S)


def code_only(text):
    """The text with strings, characters and comments blanked (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif c in "\"'":
            if c == '"' and i > 0 and text[i - 1] == "R":  # a raw string R"(…)"
                close = ")" + text[i + 1:text.find("(", i)] + '"'
                j = text.find(close, i) + len(close)
            else:
                j = i + 1
                while j < n and text[j] != c:
                    j += 2 if text[j] == "\\" else 1
                j += 1
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def long_functions(path, most, most_class=None):
    with open(path, encoding="utf-8") as f:
        code = code_only(f.read())
    found, stack, head_start = [], [], 0
    for i, c in enumerate(code):
        if c == "{":
            head = code[head_start:i]
            is_function = bool(FUNCTION.search(head)) and not CONTROL.search(head.strip().split("\n")[-1])
            is_class = most_class is not None and bool(CLASS.search(head))
            stack.append((i, "function" if is_function else "class" if is_class else "", head.strip().split("\n")[-1].strip()))
            head_start = i + 1
        elif c == "}":
            if stack:
                start, kind, head = stack.pop()
                lines = code.count("\n", start, i) + 1
                limit = most if kind == "function" else most_class if kind == "class" else None
                if limit is not None and lines > limit:
                    found.append((code.count("\n", 0, start) + 1, lines, head, kind, limit))
            head_start = i + 1
        elif c == ";":
            head_start = i + 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--most", type=int, required=True)
    parser.add_argument("--most-class", type=int, default=None)
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    problems = 0
    for path in args.files:
        for line, length, head, kind, limit in long_functions(path, args.most, args.most_class):
            print(f"{path}:{line}: a {kind} of {length} lines (at most {limit}): {head[:80]}")
            problems += 1
    classes = f" or class(es) over {args.most_class}" if args.most_class is not None else ""
    print(f"{len(args.files)} files: {problems} function(s) over {args.most} lines{classes}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
