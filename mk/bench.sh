#!/bin/sh
# `make bench`: the standard benchmark.
set -eu
build=${1:-build}
"$build/shadecalc" bench
