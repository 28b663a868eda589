#!/usr/bin/env python3
"""A derivation audit (generated/**/AUDIT.md) as a standalone HTML page with its math typeset.

The audit's Markdown is the subset billiards-derive writes: headings, paragraphs, tables, bullet
lists, inline code, bold, italics, links and $...$ math. The page puts the summary table first, gives
every claim an anchor named by its id (page.html#claim.id), shows the figures given with --figure
after the section they belong to (copied beside the page), and loads MathJax from Debian's
libjs-mathjax copied beside the manual (../mathjax), falling back to the system copy, so it works
offline and from file://.

Usage: audit_html.py --markdown AUDIT.md --out page.html [--figure "SECTION TITLE=FILE.svg|caption"]...
Exit status 0, or 2 with one line naming what was wrong.
"""

import argparse
import html
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "tools"))
from atomic_write import copy_atomically, write_atomically  # noqa: E402

MATHJAX_CONFIG = (
    'MathJax.Hub.Config({tex2jax: {inlineMath: [["\\\\(", "\\\\)"]], displayMath: [["\\\\[", "\\\\]"]], '
    'processEscapes: false}, TeX: {extensions: ["AMSmath.js", "AMSsymbols.js"]}, messageStyle: "none"});'
)
SYSTEM_MATHJAX = "file:///usr/share/javascript/mathjax/MathJax.js?config=TeX-AMS_CHTML"

STYLE = """
body { font-family: sans-serif; max-width: 64rem; margin: 2rem auto; padding: 0 1rem; line-height: 1.5; color: #222; }
table { border-collapse: collapse; margin: 1rem 0; }
th, td { border: 1px solid #ccc; padding: 0.25rem 0.5rem; vertical-align: top; text-align: left; }
code { background: #f4f4f4; padding: 0 0.2rem; }
h3 { margin-top: 2rem; }
h3 a.self { color: #999; text-decoration: none; margin-left: 0.5rem; }
figure { margin: 1.5rem 0; }
figure img { max-width: 100%; }
nav { font-size: 0.9rem; }
"""


def fail(message):
    print(f"audit_html.py: {message}", file=sys.stderr)
    sys.exit(2)


def slug(text):
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-") or "section"


LINK = re.compile(r"\[([^\]]+)\]\(([^)\s]+)\)")


def inline(text):
    """Markdown inline markup to HTML: links around anything, then code spans (nothing inside them is
    markup), then math."""
    out, start = [], 0
    for match in LINK.finditer(text):
        out.append(inline_text(text[start : match.start()]))
        out.append('<a href="' + html.escape(match.group(2)) + '">' + inline_text(match.group(1)) + "</a>")
        start = match.end()
    out.append(inline_text(text[start:]))
    return "".join(out)


def inline_text(text):
    out = []
    for k, part in enumerate(re.split(r"(`[^`]*`)", text)):
        if k % 2 == 1:
            out.append("<code>" + html.escape(part[1:-1], quote=False) + "</code>")
            continue
        pieces = part.split("$")
        if len(pieces) % 2 == 0:  # an unpaired $ is text
            pieces[-2] += "$" + pieces.pop()
        for m, piece in enumerate(pieces):
            if m % 2 == 1:
                out.append('<span class="math">\\(' + html.escape(piece, quote=False) + "\\)</span>")
            else:
                out.append(markup(piece))
    return "".join(out)


def markup(text):
    text = re.sub(r'<a id="[^"<>]*"></a>', "", text)  # a claim's anchor is its heading's id
    text = html.escape(text, quote=False)
    text = re.sub(r"\*\*(.+?)\*\*", r"<strong>\1</strong>", text)
    text = re.sub(r"(?<![\w*])\*(?!\s)(.+?)(?<!\s)\*(?![\w*])", r"<em>\1</em>", text)
    return text


def split_cells(row):
    row = row.strip()
    if row.startswith("|"):
        row = row[1:]
    if row.endswith("|") and not row.endswith("\\|"):
        row = row[:-1]
    cells, current, k = [], "", 0
    while k < len(row):
        if row[k] == "\\" and k + 1 < len(row) and row[k + 1] == "|":
            current += "|"
            k += 2
            continue
        if row[k] == "|":
            cells.append(current.strip())
            current = ""
        else:
            current += row[k]
        k += 1
    cells.append(current.strip())
    return cells


def blocks_to_html(lines):
    """Lines of Markdown (no headings of level 1 or 2) to HTML."""
    out, k = [], 0
    while k < len(lines):
        line = lines[k]
        if not line.strip() or line.lstrip().startswith("<!--"):
            k += 1
        elif line.startswith("```"):
            end = k + 1
            while end < len(lines) and not lines[end].startswith("```"):
                end += 1
            out.append("<pre><code>" + html.escape("\n".join(lines[k + 1 : end]), quote=False) + "</code></pre>")
            k = end + 1
        elif line.startswith("### "):
            title = line[4:].strip()
            anchor = title if re.fullmatch(r"[A-Za-z0-9_.\-]+", title) else slug(title)
            out.append(
                f'<h3 id="{html.escape(anchor)}">{inline(title)}'
                f'<a class="self" href="#{html.escape(anchor)}" title="link to this claim">¶</a></h3>'
            )
            k += 1
        elif line.startswith("|"):
            rows = []
            while k < len(lines) and lines[k].startswith("|"):
                rows.append(split_cells(lines[k]))
                k += 1
            has_header = len(rows) > 1 and all(re.fullmatch(r":?-+:?", c) for c in rows[1])
            aligns = []
            if has_header:
                aligns = ["right" if c.endswith(":") and not c.startswith(":") else "" for c in rows[1]]
            out.append("<table>")
            for r, row in enumerate(rows):
                if has_header and r == 1:
                    continue
                tag = "th" if has_header and r == 0 else "td"
                cells = []
                for c, cell in enumerate(row):
                    style = ' style="text-align: right"' if c < len(aligns) and aligns[c] else ""
                    cells.append(f"<{tag}{style}>{inline(cell)}</{tag}>")
                out.append("<tr>" + "".join(cells) + "</tr>")
            out.append("</table>")
        elif re.match(r"- ", line):
            out.append("<ul>")
            while k < len(lines) and lines[k].startswith("- "):
                item = lines[k][2:]
                k += 1
                while k < len(lines) and lines[k].startswith("  ") and lines[k].strip():
                    item += " " + lines[k].strip()
                    k += 1
                out.append("<li>" + inline(item) + "</li>")
            out.append("</ul>")
        else:
            paragraph = []
            while k < len(lines) and lines[k].strip() and not re.match(r"(#|\||- |```)", lines[k]):
                paragraph.append(lines[k].strip())
                k += 1
            out.append("<p>" + inline(" ".join(paragraph)) + "</p>")
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--markdown", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--mathjax", default="../mathjax/MathJax.js")
    parser.add_argument("--figure", action="append", default=[])
    args = parser.parse_args()
    try:
        with open(args.markdown, encoding="utf-8") as f:
            text = f.read()
    except OSError as error:
        fail(f"--markdown {args.markdown}: {error.strerror}, expected a readable audit")
    lines = text.splitlines()
    if not lines or not lines[0].startswith("# "):
        fail(f"--markdown {args.markdown}: the first line is not a '# ' title, expected an audit")
    title = lines[0][2:].strip()

    figures = {}
    for spec in args.figure:
        section, sep, rest = spec.partition("=")
        path, _, caption = rest.partition("|")
        if not sep or not path:
            fail(f"--figure {spec!r}: expected 'SECTION TITLE=FILE.svg|caption'")
        if not os.path.isfile(path):
            fail(f"--figure {spec!r}: {path} is not a file")
        figures.setdefault(section.strip(), []).append((path, caption.strip()))

    # Sections by "## " heading; the text before the first is the preamble.
    preamble, sections, current = [], [], None
    for line in lines[1:]:
        if line.startswith("## "):
            current = (line[3:].strip(), [])
            sections.append(current)
        elif current is None:
            preamble.append(line)
        else:
            current[1].append(line)
    unknown = set(figures) - {name for name, _ in sections}
    if unknown:
        fail(f"--figure: no section titled {sorted(unknown)[0]!r} in {args.markdown}")
    summary = [s for s in sections if s[0] == "Summary"]
    others = [s for s in sections if s[0] != "Summary"]

    out_dir = os.path.dirname(os.path.abspath(args.out))
    os.makedirs(out_dir, exist_ok=True)
    body = [f"<h1>{inline(title)}</h1>"]
    for name, section_lines in summary:  # the summary table first
        body.append(f'<h2 id="summary">{inline(name)}</h2>')
        body.append(blocks_to_html(section_lines))
    body.append(blocks_to_html(preamble))
    body.append("<nav><p>Sections: " + " · ".join(
        f'<a href="#{slug(name)}">{inline(name)}</a>' for name, _ in others) + "</p></nav>")
    for name, section_lines in others:
        body.append(f'<h2 id="{slug(name)}">{inline(name)}</h2>')
        body.append(blocks_to_html(section_lines))
        for path, caption in figures.get(name, []):
            copy_atomically(path, os.path.join(out_dir, os.path.basename(path)))
            body.append(
                f'<figure><img src="{html.escape(os.path.basename(path))}" alt="{html.escape(caption)}">'
                f"<figcaption>{inline(caption)}</figcaption></figure>"
            )
    page = (
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        f"<title>{html.escape(title)}</title>\n<style>{STYLE}</style>\n"
        f'<script type="text/x-mathjax-config">{MATHJAX_CONFIG}</script>\n'
        f'<script src="{html.escape(args.mathjax)}?config=TeX-AMS_CHTML" onerror="var s = '
        f"document.createElement('script'); s.src = '{SYSTEM_MATHJAX}'; document.head.appendChild(s);\"></script>\n"
        "</head>\n<body>\n" + "\n".join(body) + "\n</body>\n</html>\n"
    )
    write_atomically(args.out, page)
    return 0


if __name__ == "__main__":
    sys.exit(main())
