#!/usr/bin/env python3
"""Validates JSON files against a JSON Schema of docs/ (2020-12, Debian's python3-jsonschema): the
audit's (docs/audit.schema.json) or a shot's events' (docs/events.schema.json, --kind events). Every
error is printed with the file and the place in it; exit status 1 when any file does not conform, 2 on
a bad command line or a file that is not JSON.

  check_audit_schema.py --schema docs/audit.schema.json AUDIT.json [AUDIT.json ...]
  check_audit_schema.py --schema ... [--kind events] --expect-rejected FILE.json
      (the validator's own check: each file is damaged in the ways the schema forbids, one at a time,
       and every damaged copy must be rejected)
"""
import argparse
import copy
import json
import sys

try:
    import jsonschema
except ImportError:
    print("check_audit_schema.py: the Python module jsonschema is missing (Debian: python3-jsonschema)",
          file=sys.stderr)
    sys.exit(2)


def load(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as error:
        print(f"check_audit_schema.py: {path}: {error}, expected a JSON file", file=sys.stderr)
        sys.exit(2)


def damaged(audit):
    """Copies of `audit`, each with one mistake the schema must catch."""
    first = audit["claims"][0]
    for key in ("constraints", "cases", "note", "failure", "paper_tex", "depends_on"):
        copy_ = copy.deepcopy(audit)
        del copy_["claims"][0][key]
        yield f"claim {first['id']} without '{key}'", copy_
    copy_ = copy.deepcopy(audit)
    copy_["claims"][0]["verdict"] = "probably"
    yield "a verdict that is not one of the three", copy_
    copy_ = copy.deepcopy(audit)
    copy_["claims"][0]["constraints"] = None
    yield "constraints null rather than []", copy_
    copy_ = copy.deepcopy(audit)
    copy_["claims"][0]["surprise"] = 1
    yield "a field the schema does not name", copy_
    copy_ = copy.deepcopy(audit)
    copy_["schema"] = 1
    yield "the previous format's version", copy_


def damaged_events(shot):
    """Copies of a shot's events `shot`, each with one mistake the schema must catch."""
    ball = next(i for i, e in enumerate(shot["events"]) if e["kind"] == "ball")
    cushion = next(i for i, e in enumerate(shot["events"]) if e["kind"] in ("cushion", "jaw"))
    copy_ = copy.deepcopy(shot)
    del copy_["events"][0]["kind"]
    yield "an event without its kind", copy_
    copy_ = copy.deepcopy(shot)
    copy_["events"][0]["kind"] = "bounce"
    yield "a kind that is not one of the six", copy_
    copy_ = copy.deepcopy(shot)
    copy_["events"][ball]["states"].pop()
    yield "a ball-ball event with one state", copy_
    copy_ = copy.deepcopy(shot)
    kind = copy_["events"][cushion]["kind"]
    del copy_["events"][cushion][kind]
    yield f"a {kind} event without the {kind}", copy_
    copy_ = copy.deepcopy(shot)
    copy_["start"][0]["position"].append(0.0)
    yield "a position with three numbers", copy_
    copy_ = copy.deepcopy(shot)
    copy_["physics"]["ball_restitution"] = 1.5
    yield "a restitution above 1", copy_
    copy_ = copy.deepcopy(shot)
    copy_["surprise"] = 1
    yield "a field the schema does not name", copy_


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--schema", required=True)
    parser.add_argument("--expect-rejected", action="store_true")
    parser.add_argument("--kind", choices=["audit", "events"], default="audit")
    parser.add_argument("audits", nargs="+")
    args = parser.parse_args()
    schema = load(args.schema)
    validator_class = jsonschema.validators.validator_for(schema)
    validator_class.check_schema(schema)
    validator = validator_class(schema)
    failed = False
    for path in args.audits:
        audit = load(path)
        if args.expect_rejected:
            for what, copy_ in (damaged_events if args.kind == "events" else damaged)(audit):
                if not list(validator.iter_errors(copy_)):
                    print(f"{path}: {what} was accepted, expected the schema to reject it")
                    failed = True
            if not failed:
                print(f"{path}: every damaged copy rejected")
            continue
        errors = sorted(validator.iter_errors(audit), key=lambda e: list(e.absolute_path))
        for error in errors:
            place = "/".join(str(p) for p in error.absolute_path) or "(top)"
            print(f"{path}: {place}: {error.message}")
        if errors:
            failed = True
        elif args.kind == "events":
            print(f"{path}: conforms ({len(audit['events'])} events)")
        else:
            print(f"{path}: conforms ({len(audit['claims'])} claims, {len(audit['kernels'])} kernels)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
