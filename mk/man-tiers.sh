#!/bin/sh
# Prints the man page's table of batch kernels and tiers from the binary's own table
# (`shadecalc bench --list --format csv`), so that the two never disagree:
#   sh mk/man-tiers.sh build/shadecalc      (tests/e2e/test_bench.sh compares it with the page)
set -eu
bin=${1:-build/shadecalc}
echo '.TS'
echo 'l l l lx.'
printf 'kernel\ttier\tbound\tdomain\n'
"$bin" bench --list --format csv | tail -n +2 | python3 -c '
import csv, sys
for kernel, tier, isas, bound, domain in csv.reader(sys.stdin):
    text = domain.replace("\\", "\\\\").replace("-", "\\-")
    print("%s\t%s\t%s\tT{\n%s\nT}" % (kernel, tier, bound.replace("-", "\\-"), text))
'
echo '.TE'
