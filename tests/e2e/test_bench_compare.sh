# shadecalc bench --compare A.json B.json (issue 14 §4): rows matched by their key, the ratio
# B/A of the medians checked against the reports themselves, the significance mark against
# 3 x the combined MAD; malformed, hostile and missing reports.
. tests/e2e/lib.sh

a=$e2e_tmp/a.json b=$e2e_tmp/b.json
"$SHADECALC" bench --n 64 --repeat 1 --isa scalar -o "$a" exp >/dev/null 2>&1
verdict "compare: a report" test -s "$a"

# A report with itself: every ratio 1, nothing significant, no row alone.
"$SHADECALC" bench --compare "$a" "$a" >"$e2e_tmp/self" 2>"$e2e_tmp/err"
verdict "compare self: exit 0" test $? = 0
verdict "compare self: all 1.000 ~" awk -v want="$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['rows']))" "$a")" '
    NR > 2 { rows++; if ($(NF - 1) != "1.000" || $NF != "~") bad = 1 }
    END { exit bad || rows != want }' "$e2e_tmp/self"

# B: row 0 three times slower with no dispersion (significant), row 1 1% slower with a MAD of
# 10% (not significant), row 2 dropped (only in A), a new row (only in B).
python3 - "$a" "$b" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
rows = doc["rows"]
for r in rows:
    r["ns_mad"] = 0.0
rows[0]["ns_per_elem"] *= 3
rows[1]["ns_per_elem"] *= 1.01
rows[1]["ns_mad"] = 0.1 * rows[1]["ns_per_elem"]
extra = dict(rows[2], tier="u99")
del rows[2]
rows.append(extra)
json.dump(doc, open(sys.argv[2], "w"))
PY
for f in json csv table; do
    "$SHADECALC" bench --compare "$a" "$b" -f $f >"$e2e_tmp/cmp.$f" 2>"$e2e_tmp/err"
    verdict "compare edited: $f exit 0" test $? = 0
done
verdict "compare edited: json ratios and marks" python3 - "$a" "$b" "$e2e_tmp/cmp.json" <<'PY'
import json, math, sys
A = json.load(open(sys.argv[1]))["rows"]
B = json.load(open(sys.argv[2]))["rows"]
out = json.load(open(sys.argv[3]))["rows"]
key = lambda r: (r["kernel"], r["scene"], r["isa"], r["tier"], r["n"])
a = {key(r): r for r in A}
b = {key(r): r for r in B}
got = {key(r): r for r in out}
assert set(got) == set(a) | set(b), got
for k, r in got.items():
    if k in a and k in b:
        want = b[k]["ns_per_elem"] / a[k]["ns_per_elem"]
        assert abs(r["ratio"] - want) <= 1e-5 * want, (k, r, want)
        spread = math.hypot(a[k]["ns_mad"], b[k]["ns_mad"])
        diff = abs(b[k]["ns_per_elem"] - a[k]["ns_per_elem"])
        assert r["significant"] == (diff > 3 * spread), (k, r)
        assert r["only_in"] is None
    else:
        assert r["only_in"] == ("A" if k in a else "B") and r["ratio"] is None, r
assert sum(r["significant"] is True for r in out) == 1, out
assert got[key(A[0])]["significant"] and abs(got[key(A[0])]["ratio"] - 3) < 1e-4
assert got[key(A[1])]["significant"] is False
PY
verdict "compare edited: table marks" grep -q ' \*$' "$e2e_tmp/cmp.table"
verdict "compare edited: table only in" sh -c 'grep -q "only in A" "$1" && grep -q "only in B" "$1"' sh "$e2e_tmp/cmp.table"
verdict "compare edited: csv" python3 -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert sorted(r["only_in"] for r in rows if r["only_in"]) == ["A", "B"], rows
assert [r["significant"] for r in rows].count("1") == 1, rows' "$e2e_tmp/cmp.csv"
"$SHADECALC" bench --compare "$a" "$b" -o "$e2e_tmp/cmp.out.json" >"$e2e_tmp/out" 2>&1
verdict "compare -o: the format from the extension" python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$e2e_tmp/cmp.out.json"

# Malformed, truncated and hostile reports: exit 2 with the file and the place, never a crash.
bad=$e2e_tmp/bad.json
head -c 300 "$a" >"$bad"
expect "compare truncated"  2 '' "~error: bench: $bad: line " -- bench --compare "$a" "$bad"
# refused NAME STDERR: report B is $bad, exit 2
refused() { expect "compare $1" 2 '' "$2" -- bench --compare "$a" "$bad"; }
printf '{"rows": [{"kernel": "exp"}]}' >"$bad"
refused "missing key" "error: bench: $bad: rows[0]: \"scene\" is missing or not a string"
printf '{"rows": [{"kernel": "e", "scene": "", "isa": "s", "tier": "t", "n": -1, "ns_per_elem": 1, "ns_mad": 0}]}' >"$bad"
refused "negative n" "error: bench: $bad: rows[0]: \"n\" is missing or not a non-negative number"
printf '{"rows": []}\n\n  x' >"$bad"
refused "trailing text" "error: bench: $bad: line 3, column 3: text after the value"
python3 -c 'print("[" * 100000)' >"$bad"
refused "deep nesting" "error: bench: $bad: line 1, column 66: nested deeper than 64"
printf '{"rows": "\\ud800"}' >"$bad"
refused "lone surrogate" "~high surrogate without its low half"
printf '{"rows": [{"kernel": "\001"}]}' >"$bad"
refused "control char" "~control character in a string"
python3 -c 'print("{\"rows\": [" + "1" * 100 + "]}")' >"$bad"
refused "long number" "~number longer than 64 characters"
: >"$bad"
refused "empty" "error: bench: $bad: line 1, column 1: unexpected end of input"
printf '{"rows": [1]}' >"$bad"
expect "compare row not object" 2 '' "error: bench: $bad: rows[0]: not an object" -- bench --compare "$bad" "$a"
head -c 4096 /dev/urandom >"$bad"
expect "compare random bytes" 2 '' "*" -- bench --compare "$a" "$bad"
expect "compare missing file" 1 '' "error: bench: $e2e_tmp/none.json: No such file or directory" -- bench --compare "$e2e_tmp/none.json" "$a"
expect "compare one report" 2 '' "error: bench: --compare A.json B.json: expected one report B after A" -- bench --compare "$a"

# --plot: an SVG that parses, passes the figure checks, and labels every row of the smallest n
# (the plot's points) with its name.
svg=$e2e_tmp/pareto.svg
"$SHADECALC" bench --n 64,128 --repeat 1 --isa scalar --plot "$svg" exp sqrt >"$e2e_tmp/out" 2>"$e2e_tmp/err"
verdict "plot: exit 0" test $? = 0
verdict "plot: svg_check" python3 tests/e2e/svg_check.py "$svg"
"$SHADECALC" bench --n 64,128 --repeat 1 --isa scalar -f json exp sqrt >"$e2e_tmp/rows.json" 2>/dev/null
verdict "plot: every row labelled" python3 - "$svg" "$e2e_tmp/rows.json" <<'PY'
import json, sys
import xml.etree.ElementTree as ET
ns = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[1]).getroot()
labels = {}
for g in root.iter(ns + "g"):
    if g.get("class") == "series":
        labels[g.get("data-label")] = sorted(
            t.text for t in g.iter(ns + "text") if t.get("class") == "point-label")
rows = [r for r in json.load(open(sys.argv[2]))["rows"] if r["n"] == 64 and r["max_ulp"] > 0]
for kernel in ("exp", "sqrt"):
    want = sorted(r["isa"] + ("" if r["tier"] == "loop" else " " + r["tier"])
                  for r in rows if r["kernel"] == kernel)
    assert labels[kernel] == want, (kernel, labels.get(kernel), want)
PY
expect "plot: unwritable" 1 '*' "error: bench: $e2e_tmp/no/dir/p.svg: No such file or directory" -- bench --n 16 --repeat 1 --isa scalar --tier u1 --plot "$e2e_tmp/no/dir/p.svg" sqrt
expect "plot with compare" 2 '' "error: bench: --plot draws a run, not a --compare" -- bench --compare "$a" "$a" --plot "$e2e_tmp/p.svg"
