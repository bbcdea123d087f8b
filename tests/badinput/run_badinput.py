#!/usr/bin/python3
"""Run the ESPH bad-input suite (cases.py): every case under a timeout, against its
expected outcome. A case FAILS on a crash (signal), a hang (timeout), NaN or inf in the
thermo output, an unexpected success, an unexpected error or warning, a message without
the expected word, more than that warning (outcome 'onewarning'), or (outcome 'same') thermo that differs from the base scene's.

usage: run_badinput.py --lmp LMP [--mpirun MPIRUN] --workdir DIR [--jobs N]
                       [--timeout S] [--only SUBSTRING] [--write-only]
"""
import argparse
import concurrent.futures
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cases  # noqa: E402

SIGNAL_WORDS = ("Segmentation fault", "Caught signal", "Signal:", "signal 11", "Aborted",
                "core dumped", "AddressSanitizer", "runtime error:", "LeakSanitizer")


def parse_args():
    p = argparse.ArgumentParser()
    p.add_argument("--lmp", required=True)
    p.add_argument("--mpirun", default="mpirun")
    p.add_argument("--workdir", required=True)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--timeout", type=float, default=60.0)
    p.add_argument("--only", default="", help="run only the cases whose name contains this")
    p.add_argument("--write-only", action="store_true", help="write the inputs, run nothing")
    a = p.parse_args()
    a.lmp = os.path.abspath(a.lmp) if os.path.exists(a.lmp) else a.lmp
    a.workdir = os.path.abspath(a.workdir)
    return a


def thermo_rows(text):
    """thermo lines of all runs (between a 'Step' header and 'Loop time')"""
    rows, inside = [], False
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            inside = True
            rows.append(line.strip())
        elif line.startswith("Loop time"):
            inside = False
        elif inside and words:
            rows.append(line.strip())
    return rows


def messages(text, kind):
    """ERROR or WARNING messages (the line and, for errors, what follows it)"""
    out = []
    lines = text.splitlines()
    for k, line in enumerate(lines):
        if re.match(r"^(%s)( on proc \d+)?: " % kind, line):
            out.append(" ".join(lines[k:k + 3]) if kind == "ERROR" else line)
    return out


def run_case(args, name, text, np):
    d = os.path.join(args.workdir, name)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "in.case"), "w") as f:
        f.write(text)
    cmd = [args.lmp, "-in", "in.case", "-log", "none", "-nocite"]
    if np > 1:
        cmd = [args.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(np)] + cmd
    t0 = time.time()
    try:
        r = subprocess.run(cmd, cwd=d, capture_output=True, text=True, timeout=args.timeout,
                           errors="replace")
        rc, out = r.returncode, r.stdout + r.stderr
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) \
            else (e.stdout or "")
        rc = None
    with open(os.path.join(d, "output"), "w") as f:
        f.write(out)
    return rc, out, time.time() - t0


def judge(expect, rc, out, base):
    """'' if the outcome is the expected one, else why not"""
    if rc is None:
        return "hang (timeout)"
    if rc < 0 or rc >= 128 or any(w in out for w in SIGNAL_WORDS):
        return "crash (rc %s)" % rc
    rows = thermo_rows(out)
    if any(re.search(r"\b-?(nan|inf)\b", row, re.I) for row in rows[1:] if row[:4] != "Step"):
        return "NaN or inf in thermo"
    errors = messages(out, "ERROR")
    warnings = [w for w in messages(out, "WARNING") if w not in base["warnings"]]
    kind, _, word = expect.partition(":")
    if kind == "error":
        if rc == 0 or not errors:
            return "unexpected success (no ERROR)" if rc == 0 else "failed without an ERROR"
        if not any(word in e for e in errors):
            return "unexpected message: %s (expected the word '%s')" % (errors[0], word)
        return ""
    if rc != 0 or errors:
        return "unexpected error: %s" % (errors[0] if errors else "rc %d" % rc)
    if not rows:
        return "no thermo output"
    if kind in ("warning", "onewarning"):
        if not any(word in w for w in warnings):
            return "expected a warning with '%s', got %s" % (word, warnings or "none")
        if kind == "onewarning" and len(warnings) > 1:
            return "expected that warning alone, got %d: %s" % (len(warnings), warnings)
        return ""
    if warnings:
        return "unexpected warning: %s" % warnings[0]
    if kind == "same" and rows != base["rows"]:
        diff = next((a, b) for a, b in zip(rows + [""] * len(base["rows"]),
                                           base["rows"] + [""] * len(rows)) if a != b)
        return "thermo differs from the base: '%s' vs '%s'" % diff
    if kind not in ("same", "runs"):
        return "unknown expected outcome %s" % expect
    return ""


def main():
    args = parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    todo = [c for c in cases.CASES if args.only in c[0]]
    names = [c[0] for c in cases.CASES]
    dup = {n for n in names if names.count(n) > 1}
    if dup:
        print("duplicate case names:", sorted(dup))
        return 1
    if args.write_only:
        for c in todo:
            d = os.path.join(args.workdir, c[0])
            os.makedirs(d, exist_ok=True)
            with open(os.path.join(d, "in.case"), "w") as f:
                f.write(cases.build(c[1]))
        print("wrote %d inputs under %s" % (len(todo), args.workdir))
        return 0

    t0 = time.time()
    rc, out, _ = run_case(args, "base", cases.build([]), 1)
    base = {"rows": thermo_rows(out), "warnings": messages(out, "WARNING")}
    if rc != 0 or len(base["rows"]) < 2 or messages(out, "ERROR"):
        print("FAILED: the base scene does not run:\n" + out[-3000:])
        return 1
    bad = judge("same", rc, out, base)
    if bad:
        print("FAILED: base scene: " + bad)
        return 1

    failed = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {}
        for c in todo:
            name, ops, expect = c[0], c[1], c[2]
            np = c[3] if len(c) > 3 else 1
            futures[pool.submit(run_case, args, name, cases.build(ops), np)] = (name, expect, np)
        for fut in concurrent.futures.as_completed(futures):
            name, expect, np = futures[fut]
            rc, out, dt = fut.result()
            why = judge(expect, rc, out, base)
            tag = "np %d " % np if np > 1 else ""
            if why:
                failed.append(name)
                print("FAIL %-34s %s%-40s %s" % (name, tag, expect, why))
                sys.stdout.write("     " + "\n     ".join(out.strip().splitlines()[-6:]) + "\n")
            else:
                print("ok   %-34s %s%-40s %.1f s" % (name, tag, expect, dt))
            sys.stdout.flush()
    print("%d passed, %d failed (%d cases, %.0f s)" % (len(todo) - len(failed), len(failed),
                                                       len(todo), time.time() - t0))
    if failed:
        print("failed: " + " ".join(sorted(failed)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
