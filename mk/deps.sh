#!/bin/sh
# Installs the Debian packages the build and the tests need, only those missing.
# Called by `make deps` (and so by `make all` and `make check`).
#
#   required   libcmocka-dev libopenexr-dev pkg-config clang clang-format libclang-rt-14-dev python3
#              libmpfr-dev
#              (python3: the end-to-end tests parse the SVG and JSON output with a real parser;
#              MPFR: the correct-rounding checker of test_exhaustive and `make exhaustive`)
#   optional   libsleef-dev: `shadecalc bench` times SLEEF's AVX2 functions beside ours.
#              Without it the build and every test still pass; bench only lacks those rows.
#              gcovr: only `make coverage` needs it.
#              libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri: Mesa's llvmpipe through a
#              surfaceless EGL context, the GLSL ES reference of tests/e2e/test_mesa.sh.
#
# As root, every missing package is installed. Otherwise a missing required package is an error
# and a missing optional one a notice.
set -eu
required="libcmocka-dev libopenexr-dev pkg-config clang clang-format libclang-rt-14-dev python3 libmpfr-dev"
optional="libsleef-dev gcovr libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri"

missing() { # PACKAGES...: prints those not installed
    for pkg in "$@"; do
        dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' ||
            printf ' %s' "$pkg"
    done
}

command -v dpkg-query >/dev/null 2>&1 || exit 0 # not Debian: the build finds what it finds
need_req=$(missing $required)
need_opt=$(missing $optional)
[ -z "$need_req$need_opt" ] && exit 0
if [ "$(id -u)" != 0 ]; then
    if [ -n "$need_req" ]; then
        echo "deps: missing Debian packages:$need_req (run 'make deps' as root, or install them)" >&2
        exit 1
    fi
    echo "deps: optional packages not installed:$need_opt (see mk/deps.sh for what each adds)" >&2
    exit 0
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
if [ -n "$need_req" ]; then
    echo "deps: installing$need_req" >&2
    apt-get install -y -qq --no-install-recommends $need_req >/dev/null
fi
if [ -n "$need_opt" ]; then
    echo "deps: installing$need_opt (optional)" >&2
    apt-get install -y -qq --no-install-recommends $need_opt >/dev/null ||
        echo "deps: could not install optional$need_opt (see mk/deps.sh for what each adds)" >&2
fi
