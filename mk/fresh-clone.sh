#!/bin/sh
# Proves the README's test command on a fresh clone: clones this repository's HEAD into an empty
# temporary directory and runs `make check` there, once as the machine is and once as if the
# optional libsleef-dev were absent (NO_SLEEF=1). Extra arguments go to both make runs
# (e.g. CC=clang). Called by `make check-fresh`; prints the directory it used and the outcome.
set -eu
repo=$(git rev-parse --show-toplevel)
work=$(mktemp -d "${TMPDIR:-/tmp}/shadecalc-fresh.XXXXXX")
trap 'rm -rf "$work"' EXIT
git clone -q "$repo" "$work/shadecalc"
cd "$work/shadecalc"
echo "check-fresh: clone of $(git rev-parse --short HEAD) in $work/shadecalc"
echo "check-fresh: make check $*"
make check "$@"
echo "check-fresh: make check NO_SLEEF=1 $*"
make check NO_SLEEF=1 "$@"
echo "check-fresh: both passed"
