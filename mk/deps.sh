#!/bin/sh
# Installs the Debian packages the build and the tests need, only those missing.
# Called by `make deps` (and so by `make all` and `make check`). python3 is for the end-to-end
# tests only: they parse the SVG and JSON output with a real parser.
set -eu
need=""
for pkg in libcmocka-dev libopenexr-dev pkg-config clang libclang-rt-14-dev python3 libmpfr-dev; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || need="$need $pkg"
done
[ -z "$need" ] && exit 0
if [ "$(id -u)" != 0 ]; then
    echo "deps: missing Debian packages:$need (run 'make deps' as root, or install them)" >&2
    exit 1
fi
echo "deps: installing$need" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends $need >/dev/null
