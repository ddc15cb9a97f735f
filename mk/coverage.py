#!/usr/bin/env python3
"""Reads gcovr's JSON summary and checks the coverage targets of `make coverage`:
every source file at least MIN_FILE_LINES % of its lines, the whole at least MIN_BRANCHES % of
its branches. Prints a table of the files, worst first, and exits 1 when a target is missed."""
import json
import sys

MIN_FILE_LINES = 90.0
MIN_BRANCHES = 85.0


def percent(covered, total):
    return 100.0 * covered / total if total else 100.0


def main(path):
    with open(path, encoding="utf-8") as f:
        summary = json.load(f)
    files = sorted(summary["files"], key=lambda e: percent(e["line_covered"], e["line_total"]))
    print(f"{'file':44} {'lines':>8} {'branches':>9}")
    missed = []
    for e in files:
        lines = percent(e["line_covered"], e["line_total"])
        branches = percent(e["branch_covered"], e["branch_total"])
        mark = "" if lines >= MIN_FILE_LINES else "  < %.0f%%" % MIN_FILE_LINES
        print(f"{e['filename']:44} {lines:7.1f}% {branches:8.1f}%{mark}")
        if mark:
            missed.append(e["filename"])
    total_lines = percent(summary["line_covered"], summary["line_total"])
    total_branches = percent(summary["branch_covered"], summary["branch_total"])
    total_functions = percent(summary["function_covered"], summary["function_total"])
    print(f"{'TOTAL':44} {total_lines:7.1f}% {total_branches:8.1f}%   functions {total_functions:.1f}%")
    ok = True
    if missed:
        print(f"coverage: {len(missed)} files below {MIN_FILE_LINES:.0f}% of lines", file=sys.stderr)
        ok = False
    if total_branches < MIN_BRANCHES:
        print(f"coverage: branches {total_branches:.1f}% < {MIN_BRANCHES:.0f}%", file=sys.stderr)
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
