#!/usr/bin/env python3
"""The front page true to the run: runs billiards-derive and checks that the README quotes it.

Usage: check_front_page.py --derive BIN [--readme README.md] [--guides PAGE ...]

- the quick-start's sample output is billiards-derive's output, with its folder written build/audit;
- the audit paragraph's figures are the run's: the paper's claims and verified claims ("(84 claims, 83
  verified,"), the claims of each further model ("derives 68 more", "the cue strike 37");
- each model's audit (AUDIT.md, as the run writes it) is linked as generated/<path>;
- a summary line quoted in a guide (`claims: N  verified: V  failed: F  assumptions: A`) is one the run
  prints, unless it stands under the heading of a model the run does not hold (another program's run).
Exits 1 listing every difference, 0 when there is none.
"""
import argparse
import re
import subprocess
import sys
import tempfile


def run(derive):
    with tempfile.TemporaryDirectory() as out:
        done = subprocess.run([derive, "--out", out], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if done.returncode != 0:
            sys.exit(f"check_front_page: {derive} exited {done.returncode}:\n{done.stderr}")
        return done.stdout.replace(out + "/", "build/audit/")


def models_of(output):
    """Each model's citation, its summary numbers and the audits it wrote, in the run's order."""
    models = []
    for block in re.split(r"(?m)^(?=Derivation audit of )", output):
        if not block.strip():
            continue
        citation = block.splitlines()[0][len("Derivation audit of "):]
        numbers = re.search(r"claims: (\d+)  verified: (\d+)  failed: (\d+)  assumptions: (\d+)", block)
        audits = re.findall(r"build/audit/(\S*AUDIT\.md)", block)
        models.append({"citation": citation, "claims": int(numbers[1]), "verified": int(numbers[2]),
                       "summary": numbers[0], "audits": audits})
    return models


def check(readme_text, guides, output):
    problems = []
    models = models_of(output)
    if not models:
        return ["the run printed no model's summary"]
    block = re.search(r"```\n(Derivation audit of .*?)```", readme_text, re.S)
    if not block:
        problems.append("README.md: no sample output of ./tools/derive (a ``` block from 'Derivation audit of')")
    elif block[1] != output:
        problems.append(f"README.md: the sample output of ./tools/derive is not the run's; the run prints:\n{output}")
    paper = models[0]
    quoted = f"({paper['claims']} claims, {paper['verified']} verified,"
    if quoted not in readme_text:
        problems.append(f"README.md: the audit paragraph does not say {quoted}")
    flat = " ".join(readme_text.split())
    figures = re.findall(r"derives (\d+) more|the cue strike (\d+)", flat)
    further = sorted(m["claims"] for m in models[1:])
    said = sorted(int(a or b) for a, b in figures)
    if said != further:
        problems.append(f"README.md: the audit paragraph gives the further models {said} claims, the run {further}")
    for model in models:
        for audit in model["audits"]:
            if f"(generated/{audit})" not in readme_text:
                problems.append(f"README.md: the audit generated/{audit} ({model['citation']}) is not linked")
    summaries = {m["summary"] for m in models}
    citations = {m["citation"] for m in models}
    summary = re.compile(r"(?:Derivation audit of (.*)\n\s*)?(claims: \d+  verified: \d+  failed: \d+  assumptions: \d+)")
    for path, text in guides:
        for citation, line in summary.findall(text):
            # A summary under another program's heading (a model of one's own) is that program's.
            if citation and citation not in citations:
                continue
            if line not in summaries:
                problems.append(f"{path}: quotes `{line}`, which the run does not print")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--derive", required=True)
    parser.add_argument("--readme", default="README.md")
    parser.add_argument("--guides", nargs="*", default=[])
    args = parser.parse_args()
    output = run(args.derive)
    with open(args.readme, encoding="utf-8") as f:
        readme_text = f.read()
    guides = []
    for path in args.guides:
        with open(path, encoding="utf-8") as f:
            guides.append((path, f.read()))
    problems = check(readme_text, guides, output)
    for problem in problems:
        print(problem)
    pages = f"{args.readme} and {len(guides)} guide(s)"
    print(f"{pages}: {'true to the run' if not problems else f'{len(problems)} difference(s) from the run'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
