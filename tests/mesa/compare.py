#!/usr/bin/env python3
"""Compares `shadecalc eval` (highp) with Mesa's llvmpipe (mesa_eval) on the cases of
tests/mesa/*.cases.

A case is a line `TYPE<TAB>EXPR` or `TYPE ~N<TAB>EXPR` (results may differ by N binary32 ULPs:
functions whose order of operations GLSL leaves open, such as length or normalize). Lines
starting with `@` are code (functions, constants) for the cases after them: those cases run
through `shadecalc eval --file`. Where Mesa rejects a case, shadecalc must reject it too (exit
status 2); elsewhere both give the same components. Blank lines and `#` lines are skipped.

usage: compare.py MESA_EVAL SHADECALC CASES...
Exit status 0 when every case agrees, 1 otherwise.
"""
import math
import re
import struct
import subprocess
import sys
import tempfile

TOKEN = re.compile(r"(?<![A-Za-z0-9_.])(?:true|false|[-+]?(?:inf(?:inity)?|nan|(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?))",
                   re.IGNORECASE)


def parse_cases(path):
    """(prelude, type, tolerance, expr, line number) for each case of the file."""
    prelude, cases = [], []
    with open(path, encoding="utf-8") as f:
        for lineno, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            if line.startswith("@"):
                prelude.append(line[1:])
                continue
            head, _, expr = line.partition("\t")
            glsl_type, _, tol = head.partition(" ~")
            cases.append(("\n".join(prelude), glsl_type, int(tol or 0), expr, lineno))
    return cases


def run_mesa(mesa_eval, cases):
    """Mesa's output line for each case: one mesa_eval run per distinct prelude, since
    mesa_eval keeps the `@` lines of a run for every case after them."""
    outputs = []
    for run_input in split_runs(cases):
        r = subprocess.run([mesa_eval], input=run_input, capture_output=True, text=True,
                           check=False)
        if r.returncode != 0:
            raise RuntimeError(f"mesa_eval failed ({r.returncode}): {r.stderr.strip()}")
        outputs += r.stdout.splitlines()
    return outputs


def split_runs(cases):
    """One mesa_eval input per distinct prelude, in case order."""
    runs, current, last = [], "", None
    for prelude, glsl_type, _, expr, _ in cases:
        if prelude != last and current:
            runs.append(current)
            current = ""
        if prelude != last:
            current += "".join("@" + p + "\n" for p in prelude.split("\n") if prelude)
            last = prelude
        current += f"{glsl_type}\t{expr}\n"
    if current:
        runs.append(current)
    return runs


def run_shadecalc(shadecalc, prelude, expr):
    """(exit status, standard output) of shadecalc on one case."""
    if not prelude:
        r = subprocess.run([shadecalc, "eval", "--", expr], capture_output=True, text=True,
                           check=False)
        return r.returncode, r.stdout
    with tempfile.NamedTemporaryFile("w", suffix=".glsl", encoding="utf-8") as f:
        f.write(prelude + "\n" + expr + "\n")
        f.flush()
        r = subprocess.run([shadecalc, "eval", "--file", f.name], capture_output=True,
                           text=True, check=False)
        return r.returncode, r.stdout


def as_float32(token):
    return struct.unpack("<f", struct.pack("<f", float(token)))[0]


def ordered(x):
    """The binary32 bit pattern of x as an integer ordered like the reals."""
    (bits,) = struct.unpack("<i", struct.pack("<f", x))
    return bits if bits >= 0 else -(bits & 0x7FFFFFFF)


def same_component(a, b, tol):
    if a in ("true", "false") or b in ("true", "false"):
        return a.lower() == b.lower()
    x, y = as_float32(a), as_float32(b)
    if math.isnan(x) or math.isnan(y):
        return math.isnan(x) and math.isnan(y)
    if math.isinf(x) or math.isinf(y):
        return x == y
    return abs(ordered(x) - ordered(y)) <= tol


def judge(case, mesa_line, status, out):
    """None when shadecalc agrees with Mesa, else what differs."""
    _, _, tol, _, _ = case
    if mesa_line == "error":
        return None if status == 2 else f"Mesa rejects it; shadecalc exits {status}: {out.strip()}"
    if status != 0:
        return f"Mesa gives {mesa_line}; shadecalc exits {status}"
    want, got = TOKEN.findall(mesa_line), TOKEN.findall(out.strip().splitlines()[-1])
    if len(want) != len(got) or not all(same_component(a, b, tol) for a, b in zip(want, got)):
        return f"Mesa gives {mesa_line}; shadecalc {out.strip()}"
    return None


def main(argv):
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    mesa_eval, shadecalc, files = argv[1], argv[2], argv[3:]
    failures = total = 0
    for path in files:
        cases = parse_cases(path)
        for case, mesa_line in zip(cases, run_mesa(mesa_eval, cases)):
            total += 1
            status, out = run_shadecalc(shadecalc, case[0], case[3])
            problem = judge(case, mesa_line, status, out)
            if problem:
                failures += 1
                print(f"FAIL {path}:{case[4]}: {case[3]}: {problem}")
    print(f"mesa: {total - failures} of {total} cases agree")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
