#!/bin/sh
# End-to-end tests: runs every tests/e2e/test_*.sh (or the scripts given) against the binary
# given, one after the other (`make e2e` runs them in parallel), each through tests/run-test.sh:
# its output is printed when it fails, kept in a temporary directory otherwise.
#   sh tests/e2e/run.sh BIN [tests/e2e/test_NAME.sh...]
set -u
SHADECALC=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
export SHADECALC
shift
[ $# -gt 0 ] || set -- tests/e2e/test_*.sh
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT
names=""
for t in "$@"; do
    name=$(basename "$t" .sh)
    names="$names $name"
    sh tests/run-test.sh "$results" "$name" sh "$t"
done
# shellcheck disable=SC2086 # names are file names without spaces
sh tests/run-test.sh --summary "$results" e2e $names
