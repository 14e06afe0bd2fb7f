#!/usr/bin/env python3
"""The interop report of docs/interop.md: opens, runs and round-trips a corpus of PLCopen
XML projects with `plc`, and tallies the causes of the failures.

An opt-in check: the corpus is other people's projects, which the repository does not
carry, and the default test suite does not run this script.

Usage: PLC_INTEROP_CORPUS=DIR python3 scripts/interop.py [PLC] [--tsv OUT.tsv]
       python3 scripts/interop.py PLC DIR [--tsv OUT.tsv]

DIR (the second argument, else $PLC_INTEROP_CORPUS) holds the `.xml` files, any layout
below it. PLC is the `plc` binary, by default target/release/plc of this repository
(`cargo build -p plc-core --release --bin plc`). For each file:
  opens       `plc run FILE --cycles 0 --json` has no E0304 (the import succeeded)
  runs        `plc run FILE --cycles 20 --json` ends with status "ok"
  round-trips the file imported (`plc import`), exported again (`plc export --plcopen`)
              and run for 20 scans gives the same variables as the file itself
The cause of a failure is the first error's code and the start of its message, with
names and numbers folded so that files failing for one reason count together.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
from collections import Counter

CYCLES = "20"


def plc(binary, *args):
    try:
        out = subprocess.run([binary, *args], capture_output=True, text=True, timeout=60)
        return out.returncode, out.stdout
    except subprocess.TimeoutExpired:
        return 124, ""


def report(binary, path, *extra):
    code, out = plc(binary, "run", path, "--cycles", CYCLES, "--json", *extra)
    try:
        return json.loads(out)
    except json.JSONDecodeError:
        return {"status": "crash", "diagnostics": [], "vars": {}, "exit": code}


def cause(rep):
    for d in rep.get("diagnostics", []):
        if d.get("severity") == "error":
            msg = re.sub(r"`[^`]*`", "`…`", d["message"])
            msg = re.sub(r"localId \S+", "localId N", msg)
            msg = re.sub(r"POU [^,:]+", "POU P", msg)
            msg = re.sub(r"rung \d+, row \d+, column \d+", "rung r", msg)
            msg = re.sub(r"declarations line \d+, column \d+", "declarations", msg)
            msg = re.sub(r"%[IQM]\S+", "%…", msg)
            return f"{d['code']} {msg[:110]}"
    if rep.get("status") == "fault":
        return "fault: " + (rep.get("fault") or {}).get("message", "")[:80]
    return rep.get("status", "?")


def arguments():
    """(plc binary, corpus folder, tsv path or None); exits saying why when one is missing."""
    args = sys.argv[1:]
    tsv = None
    if "--tsv" in args:
        k = args.index("--tsv")
        if k + 1 >= len(args):
            sys.exit("--tsv needs a file name\n\n" + __doc__)
        tsv = args[k + 1]
        del args[k : k + 2]
    if len(args) > 2 or any(a.startswith("-") for a in args):
        sys.exit(__doc__)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    binary = args[0] if args else os.path.join(root, "target", "release", "plc")
    corpus = args[1] if len(args) > 1 else os.environ.get("PLC_INTEROP_CORPUS", "")
    if not corpus:
        sys.exit(
            "PLC_INTEROP_CORPUS is not set and no corpus folder was given: nothing to check.\n"
            "This check is opt-in (the default test suite does not run it); point it at a\n"
            "folder of PLCopen XML files, e.g.\n"
            "  PLC_INTEROP_CORPUS=~/plcopen-corpus python3 scripts/interop.py\n"
            "docs/interop.md says how the reported corpus was gathered."
        )
    if not os.path.isdir(corpus):
        sys.exit(f"the corpus folder {corpus} does not exist")
    if not os.access(binary, os.X_OK):
        sys.exit(f"no plc binary at {binary}: build it with "
                 "`cargo build -p plc-core --release --bin plc`, or name one")
    return binary, corpus, tsv


def main():
    binary, corpus, tsv = arguments()
    files = sorted(
        os.path.join(d, f) for d, _, fs in os.walk(corpus) for f in fs if f.endswith(".xml")
    )
    tally = Counter()
    causes = Counter()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for path in files:
            rep = report(binary, path)
            codes = [d["code"] for d in rep.get("diagnostics", []) if d.get("severity") == "error"]
            opens = "E0304" not in codes and rep.get("status") != "crash"
            runs = rep.get("status") == "ok"
            trip = False
            if runs:
                code, project = plc(binary, "import", path)
                proj = os.path.join(tmp, "p.plcproj.json")
                with open(proj, "w") as f:
                    f.write(project)
                code, xml = plc(binary, "export", "--plcopen", proj)
                back = os.path.join(tmp, "back.xml")
                with open(back, "w") as f:
                    f.write(xml)
                again = report(binary, back)
                trip = again.get("status") == "ok" and again.get("vars") == rep.get("vars")
            tally["files"] += 1
            tally["opens"] += opens
            tally["runs"] += runs
            tally["round-trips"] += trip
            why = "" if runs else cause(rep)
            if not runs:
                causes[why] += 1
            elif not trip:
                causes["runs, but the exported file does not run the same"] += 1
            rows.append((os.path.basename(path), opens, runs, trip, why))
    print(f"files {tally['files']}, open {tally['opens']}, run {tally['runs']}, "
          f"round-trip {tally['round-trips']}")
    print()
    print("| count | cause |")
    print("|---:|---|")
    for why, n in causes.most_common():
        print(f"| {n} | {why} |")
    if tsv:
        with open(tsv, "w") as f:
            f.write("file\topens\truns\tround_trips\tcause\n")
            for r in rows:
                f.write("\t".join(str(x) for x in r) + "\n")


if __name__ == "__main__":
    main()
