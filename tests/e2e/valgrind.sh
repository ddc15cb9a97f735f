#!/bin/sh
# make check-valgrind: the end-to-end tests with every run of the binary under valgrind's
# memcheck. An invalid read or write, a use of uninitialised memory or a definite leak makes
# that run exit 99 and print valgrind's report on its standard error, so the test that ran it
# fails and shows the report. Tests that need an address-space limit skip themselves (valgrind
# does not start under one), as they do for sanitizer builds.
set -eu
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
command -v valgrind >/dev/null || { echo "check-valgrind: valgrind is not installed" >&2; exit 1; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat >"$dir/shadecalc" <<WRAP
#!/bin/sh
exec valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite \\
    --show-leak-kinds=definite "$bin" "\$@"
WRAP
chmod +x "$dir/shadecalc"
sh tests/e2e/run.sh "$dir/shadecalc"
