#!/usr/bin/python3
"""Runs one example of examples/ as the estimator or the controller of a short `hil run` (virtual
mode) and checks the run completed, was judged, and got the verdict examples/README.md gives for
it: pass, or fail on exactly the criteria named there. Debian's python3, standard library only.

Usage: example_run.py --hil HIL --scenario YAML --out DIR (--estimator CMD | --controller CMD)
                      --expect pass|fail [--failing NAME ...] [--set FIELD=VALUE ...] [--short]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--hil", required=True)
    ap.add_argument("--scenario", required=True)
    ap.add_argument("--out", required=True)
    role = ap.add_mutually_exclusive_group(required=True)
    role.add_argument("--estimator")
    role.add_argument("--controller")
    ap.add_argument("--expect", choices=("pass", "fail"), required=True)
    ap.add_argument("--failing", nargs="*", default=[],
                    help="the criteria (report.json criteria[].name prefixes) that fail")
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--short", action="store_true", help="the scenario's short form")
    a = ap.parse_args()

    shutil.rmtree(a.out, ignore_errors=True)
    cmd = [a.hil, "run", a.scenario, "--mode", "virtual", "--no-html", "--out", a.out]
    if a.short:
        cmd.append("--short")
    if a.estimator:
        cmd += ["--estimator", a.estimator]
    else:
        a.set.append("closed_loop.controller=" + json.dumps(a.controller))
    for s in a.set:
        cmd += ["--set", s]
    print("+", " ".join(cmd), flush=True)
    rc = subprocess.run(cmd).returncode
    errors = []
    try:
        with open(os.path.join(a.out, "report.json")) as f:
            r = json.load(f)
    except (OSError, ValueError) as e:
        print("example_run: no report.json (hil exit %d): %s" % (rc, e), file=sys.stderr)
        return 1

    if not r.get("complete"):
        errors.append("the run did not complete: %s" % r.get("incomplete_reason"))
    if r.get("problems"):
        errors.append("problems: %s" % r["problems"])
    criteria = r.get("criteria", [])
    if not criteria:
        errors.append("the run was not judged (no criteria)")
    if r["metrics"].get("samples", 0) == 0:
        errors.append("no solution was scored")
    words = (a.estimator or a.controller).split()
    program = words[1] if words[0].endswith("python3") else words[0]  # the example's own file
    if a.estimator and program not in r.get("estimator", {}).get("command", ""):
        errors.append("the example was not the estimator: %s" % r.get("estimator"))
    if a.controller:
        cl = r.get("closed_loop", {})
        if program not in cl.get("controller_command", ""):
            errors.append("the example was not the controller: %s" % cl.get("controller_command"))
        if not cl.get("motor_commands"):
            errors.append("the controller sent no command")
        print("example_run: closed loop: motor commands %s, missing %s, cross-track mean |e| %s m" % (
            cl.get("motor_commands"), cl.get("missing_commands"),
            r.get("tracking", {}).get("cross_track_mean_abs_m")))
    failed = sorted(c["name"] for c in criteria if not c["pass"])
    for c in criteria:
        print("example_run: %-4s %s (value %s, bound %s)" % (
            "PASS" if c["pass"] else "FAIL", c["name"], c["value"], c["threshold"]))
    verdict = "pass" if r.get("pass") else "fail"
    if verdict != a.expect:
        errors.append("verdict %s, examples/README.md says %s" % (verdict, a.expect))
    if (rc == 0) != (a.expect == "pass"):
        errors.append("hil exit %d with the expected verdict %s" % (rc, a.expect))
    for name in a.failing:
        if not any(f.startswith(name) for f in failed):
            errors.append("criterion %s passed; examples/README.md says it fails" % name)
    for f in failed:
        if not any(f.startswith(name) for name in a.failing):
            errors.append("criterion %s failed; examples/README.md does not say so" % f)
    for e in errors:
        print("example_run: " + e, file=sys.stderr)
    if not errors:
        print("example_run: verdict %s as examples/README.md says%s" % (
            verdict, " (failing: %s)" % ", ".join(failed) if failed else ""))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
