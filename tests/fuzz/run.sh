#!/bin/sh
# Runs each libFuzzer harness given for a bounded time, seeded from tests/fuzz/corpus/NAME/
# (make fuzz runs them in parallel, one at a time here); fails at the first that fails.
set -eu
secs=$1; shift
for f in "$@"; do
    name=$(basename "$f")
    seeds=tests/fuzz/corpus/$name
    work=$(mktemp -d)
    [ -d "$seeds" ] && cp -r "$seeds/." "$work/"
    echo "fuzz: $name for ${secs}s"
    if ! "$f" -max_total_time="$secs" -max_len=65536 -timeout=5 -rss_limit_mb=2048 \
        -print_final_stats=0 \
        -artifact_prefix="build-fuzz/$name-" "$work" >"build-fuzz/$name.log" 2>&1; then
        tail -40 "build-fuzz/$name.log" >&2
        echo "fuzz: $name FAILED (log: build-fuzz/$name.log)" >&2
        rm -rf "$work"
        exit 1
    fi
    rm -rf "$work"
done
