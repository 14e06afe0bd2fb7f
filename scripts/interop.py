#!/usr/bin/env python3
"""The interop report of docs/interop.md: opens, runs and round-trips a corpus of PLCopen
XML projects with `plc`, and tallies the causes of the failures.

Usage: python3 scripts/interop.py PLC CORPUS_DIR [--tsv OUT.tsv]

CORPUS_DIR holds the `.xml` files (any layout below it). For each file:
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


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    binary, corpus = sys.argv[1], sys.argv[2]
    tsv = sys.argv[sys.argv.index("--tsv") + 1] if "--tsv" in sys.argv else None
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
