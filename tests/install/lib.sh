# Sourced by tests/install/exports.sh and run.sh, after setting TEST (the name in messages).
#   $tmp             a temporary directory, removed on exit
#   fail MESSAGE     prints "FAIL TEST: MESSAGE" and counts the failure
#   finish SUMMARY   prints "TEST: passed (SUMMARY)" and exits 0, or exits 1 if anything failed
#   $cxx_compilers   g++ and clang++, those installed
#   $strict          the warnings every test program is built with (as errors)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() {
    echo "FAIL $TEST: $*"
    fails=$((fails + 1))
}
finish() {
    [ "$fails" -eq 0 ] || exit 1
    echo "$TEST: passed ($1)"
    exit 0
}
cxx_compilers=$(for c in g++ clang++; do command -v "$c" >/dev/null && echo "$c"; done)
strict='-Wall -Wextra -Wpedantic -Werror'
