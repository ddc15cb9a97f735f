# Writes that fail for lack of space, on a 64 KiB tmpfs: the error names the file and the
# reason, the old file is kept and no temporary is left (the atomic writer's failure paths).
# Needs root's mount; skipped where mounting is refused.
. tests/e2e/lib.sh

fs=$e2e_tmp/small
mkdir -p "$fs"
if mount -t tmpfs -o size=64k tmpfs "$fs" 2>/dev/null; then
    trap 'umount "$fs" 2>/dev/null; rm -rf "$e2e_tmp"' EXIT
    printf 'old\n' >"$fs/t.csv"
    expect "full disk: table" 1 '' "~$fs/t.csv: No space left on device" -- \
        sweep --var x=0:1:100000 -o "$fs/t.csv" x
    verdict "full disk: the old table is kept" test "$(cat "$fs/t.csv")" = old
    expect "full disk: plot" 1 '' "~$fs/p.svg: No space left on device" -- \
        sweep --var x=0:1:20000 --var k=1,2,3 --plot "$fs/p.svg" 'pow(x, k)'
    expect "full disk: image" 1 '' "~$fs/r.exr" -- render --size 512x512 --exr-type float -o "$fs/r.exr"
    verdict "full disk: no temporary left" test "$(ls -A "$fs")" = t.csv
else
    echo "skip full disk (mounting a tmpfs is refused here)"
fi
