#!/bin/sh
# End-to-end tests: runs every tests/e2e/test_*.sh against the binary given.
set -u
SHADECALC=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
E2E_COUNTS=$(mktemp)
export SHADECALC E2E_COUNTS
for t in tests/e2e/test_*.sh; do
    [ -f "$t" ] || continue
    echo "== $t"
    sh "$t" || echo fail >>"$E2E_COUNTS"
done
pass=$(grep -c '^pass$' "$E2E_COUNTS"); fail=$(grep -c '^fail$' "$E2E_COUNTS")
rm -f "$E2E_COUNTS"
echo "e2e: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
