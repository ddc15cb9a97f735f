#!/bin/sh
# One test of `make unit` or `make e2e`, which run them in parallel, one make target each:
#
#   sh tests/run-test.sh RESULTS NAME COMMAND...
#       runs COMMAND (a cmocka binary, or `sh tests/e2e/test_NAME.sh`) with its output in
#       RESULTS/NAME.log, printed whole when the test fails; RESULTS/NAME.counts gets a 'pass' or
#       'fail' line per check: the e2e scripts write theirs ($E2E_COUNTS), a unit binary counts
#       as one check, and a command that exits non-zero adds a 'fail'. Exits 0: the summary
#       decides.
#   sh tests/run-test.sh --summary RESULTS WHAT NAME...
#       prints 'WHAT: N passed, N failed' and fails when a check failed or NAME left no result.
set -u

summary() {
    dir=$1 what=$2
    shift 2
    pass=0 fail=0 failed=""
    for name in "$@"; do
        counts=$dir/$name.counts
        if [ ! -f "$counts" ]; then
            failed="$failed $name(no result)"
            fail=$((fail + 1))
            continue
        fi
        p=$(grep -c '^pass$' "$counts") f=$(grep -c '^fail$' "$counts")
        pass=$((pass + p)) fail=$((fail + f))
        [ "$f" -eq 0 ] || failed="$failed $name"
    done
    echo "$what: $pass passed, $fail failed"
    [ -z "$failed" ] || { echo "$what failed:$failed (logs: $dir/NAME.log)" >&2; return 1; }
}

if [ "$1" = --summary ]; then
    shift
    summary "$@"
    exit
fi

dir=$1 name=$2
shift 2
mkdir -p "$dir"
E2E_COUNTS=$dir/$name.counts
export E2E_COUNTS
: >"$E2E_COUNTS"
if "$@" >"$dir/$name.log" 2>&1; then
    [ -s "$E2E_COUNTS" ] || echo pass >>"$E2E_COUNTS"
else
    echo "exit status $?" >>"$dir/$name.log"
    echo fail >>"$E2E_COUNTS"
fi
if grep -q '^fail$' "$E2E_COUNTS"; then
    printf '== %s FAILED: %s\n' "$name" "$*"
    cat "$dir/$name.log"
fi
exit 0
