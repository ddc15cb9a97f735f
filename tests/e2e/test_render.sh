# shadecalc render: images written atomically with the command line in the header, the
# comparison's table, files and ordering, and the errors of every option.
. tests/e2e/lib.sh

# check NAME CONDITION...: a pass or a fail for a shell test
check() {
    name=$1; shift
    if "$@"; then echo "ok   $name"; echo pass >>"$E2E_COUNTS"
    else echo "FAIL $name: $*"; echo fail >>"$E2E_COUNTS"; fi
}

imgdir=$e2e_tmp/render
mkdir -p "$imgdir"

expect "help"                    0 '~usage: shadecalc render' '' -- render --help
expect "default picture"         0 '' '' -- render --size 64x48 -o "$imgdir/sphere.exr"
check  "exr magic number"        sh -c "head -c 4 '$imgdir/sphere.exr' | od -An -tx1 | grep -q '76 2f 31 01'"
# attribute strings sit uncompressed in the EXR header
check  "command line in header"  grep -q -a 'shadecalc render --size 64x48 -o' "$imgdir/sphere.exr"
expect "depth, normals, float"   0 '' '' -- render --surface 'torus R=1 r=0.3' --shading gouraud --triangles 500 --size 40x40 --depth --normals --exr-type float -o "$imgdir/torus.exr"
check  "extra channels named"    sh -c "grep -q -a 'N.X' '$imgdir/torus.exr' && grep -q -a 'shadecalc:shading' '$imgdir/torus.exr'"
expect "quoted argument"         0 '' '' -- render --surface 'cylinder r=1 h=2' --shading flat --size 16x16 --threads 3 -o "$imgdir/cyl.exr"
check  "quoted in header"        grep -q -a "shadecalc render --surface 'cylinder r=1 h=2'" "$imgdir/cyl.exr"
expect "exact, camera options"   0 '' '' -- render --shading exact --eye 0,-4,1 --at 0,0,0 --up 0,0,1 --fov 30 --size 24x24 -p double -o "$imgdir/exact.exr"
printf 'v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\nf 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n' >"$e2e_tmp/octa.obj"
expect "obj mesh, normals made"  0 '' '' -- render --mesh "$e2e_tmp/octa.obj" --shading phong --size 16x16 -o "$imgdir/octa.exr"

# --compare: the table, its files, and the lecture's ordering at a small size
cmp=$e2e_tmp/compare
mkdir -p "$cmp"
"$SHADECALC" render --compare --size 64x64 --format csv --output-dir "$cmp" >"$e2e_tmp/table.csv" 2>"$e2e_tmp/err"
check  "compare exit status"     test $? = 0
check  "compare csv header"      test "$(head -n 1 "$e2e_tmp/table.csv")" = 'mode,triangles,seconds,rmse,max_error'
check  "compare rows"            test "$(cut -d, -f1 "$e2e_tmp/table.csv" | tr '\n' ' ')" = 'mode gouraud gouraud gouraud phong exact '
check  "compare ordering"        awk -F, 'NR == 2 { g1 = $4 } NR == 3 { g2 = $4 } NR == 4 { g3 = $4 }
                                          NR == 5 { p = $4 } NR == 6 { e = $4; m = $5 }
                                          END { exit !(e == 0 && m == 0 && p < g2 && g3 < g2 && g2 < g1) }' "$e2e_tmp/table.csv"
for f in render-gouraud-1024 render-gouraud-6320 render-gouraud-40000 render-phong-6320 render-exact \
         error-gouraud-1024 error-gouraud-6320 error-gouraud-40000 error-phong-6320; do
    check "compare wrote $f.exr" test -s "$cmp/$f.exr"
done
expect "compare table"           0 '~mode     triangles   seconds' '' -- render --compare --size 16x16 --output-dir "$cmp"

# errors name the option and what it takes; nothing is left behind
expect "no output"               2 '' 'error: render: no output: give -o FILE.exr (or --compare)' -- render
expect "bad size"                2 '' 'error: render: --size 0x5: expected WxH, each 1..16384, at most 33554432 pixels' -- render --size 0x5 -o "$imgdir/x.exr"
expect "size not WxH"            2 '' 'error: render: --size 64: expected WxH, each 1..16384, at most 33554432 pixels' -- render --size 64 -o "$imgdir/x.exr"
expect "bad shading"             2 '' 'error: render: --shading smooth: expected flat|gouraud|phong|exact' -- render --shading smooth -o "$imgdir/x.exr"
expect "bad exr type"            2 '' 'error: render: --exr-type double: expected half|float' -- render --exr-type double -o "$imgdir/x.exr"
expect "bad format"              2 '' 'error: render: --format json: expected table|csv' -- render --compare --format json
expect "bad fov"                 2 '' 'error: render: --fov 180: expected degrees between 0 and 180' -- render --fov 180 -o "$imgdir/x.exr"
expect "bad threads"             2 '' 'error: render: --threads 0: expected a whole number 1..1024' -- render --threads 0 -o "$imgdir/x.exr"
expect "bad triangles"           2 '' 'error: render: --triangles 1: expected a whole number 2..67108864' -- render --triangles 1 -o "$imgdir/x.exr"
expect "bad eye"                 2 '' 'error: render: --eye 1,2: expected three numbers X,Y,Z' -- render --eye 1,2 -o "$imgdir/x.exr"
expect "eye at target"           2 '' 'error: render: camera: --eye 0,0,0 equals --at' -- render --eye 0,0,0 --at 0,0,0 -o "$imgdir/x.exr"
expect "up along view"           2 '' 'error: render: camera: --up 0,0,1 is zero or along the view direction' -- render --eye 0,0,5 --at 0,0,0 -o "$imgdir/x.exr"
expect "bad surface"             2 '' '~error: render: --surface: ' -- render --surface blob -o "$imgdir/x.exr"
expect "surface and mesh"        2 '' 'error: render: give --surface or --mesh, not both' -- render --surface sphere --mesh "$e2e_tmp/octa.obj" -o "$imgdir/x.exr"
expect "exact needs a surface"   2 '' "error: render: --mesh $e2e_tmp/octa.obj: exact shading and --compare need an analytic --surface" -- render --mesh "$e2e_tmp/octa.obj" --shading exact -o "$imgdir/x.exr"
expect "compare and -o"          2 '' "error: render: --compare writes into --output-dir, not -o $imgdir/x.exr" -- render --compare -o "$imgdir/x.exr"
expect "anisotropic brdf"        2 '' 'error: render: brdf ward: anisotropic roughness (ax=0.1 ay=0.3) needs a tangent field, which render does not have' -- render --brdf 'ward ax=0.1 ay=0.3' -o "$imgdir/x.exr"
expect "bad light"               2 '' 'error: light point: missing pos=X,Y,Z' -- render --light point -o "$imgdir/x.exr"
expect "stray argument"          2 '' "error: render: unexpected argument 'sphere'" -- render sphere -o "$imgdir/x.exr"
expect "missing mesh file"       1 '' '~nonexistent.obj' -- render --mesh "$e2e_tmp/nonexistent.obj" -o "$imgdir/x.exr"
check  "nothing written on error" test ! -e "$imgdir/x.exr"
expect "missing directory"       1 '' "~$e2e_tmp/none/a.exr" -- render --size 8x8 -o "$e2e_tmp/none/a.exr"
check  "no temporary left"       test -z "$(ls -A "$imgdir" | grep -v -e '^sphere.exr$' -e '^torus.exr$' -e '^cyl.exr$' -e '^exact.exr$' -e '^octa.exr$')"
expect "compare dir not creatable" 1 '' "error: render: --output-dir $e2e_tmp/octa.obj: not a directory" -- render --compare --size 8x8 --output-dir "$e2e_tmp/octa.obj/sub"
expect "compare fixes its plan"  2 '' 'error: render: --compare renders its own plan (Gouraud at 1024, 6320, 40000 triangles, Phong at 6320, exact): --shading does not apply' -- render --compare --shading phong
expect "compare fixes triangles" 2 '' 'error: render: --compare renders its own plan (Gouraud at 1024, 6320, 40000 triangles, Phong at 6320, exact): --triangles does not apply' -- render --compare --triangles 100
expect "isa scalar"              0 '' '' -- render --size 16x16 --isa scalar -o "$imgdir/isa.exr"
expect "bad isa"                 2 '' 'error: render: --isa neon: expected scalar, sse4.1, avx2 or avx512' -- render --isa neon -o "$imgdir/isa.exr"

# colours beyond the range (issue 11 §7): inf with a warning, never NaN (the SIMD kernel's 0·inf
# pixels are shaded again by sc_shade)
expect "overflow warns" 0 '' '~pixels overflow to inf (beyond the float range)' -- render --light 'point pos=0,0,1.2 I=3e38' --brdf 'blinn-phong m=32' --size 96x96 --exr-type float -o "$e2e_tmp/overflow.exr"
# compression_of FILE: the value of the header's compression attribute (one byte after the
# name, the type "compression" and a 4-byte size: none 0, rle 1, zips 2, zip 3, piz 4, pxr24 5)
compression_of() {
    at=$(LC_ALL=C grep -a -o -b -m 1 'compression' "$1" | head -n 1 | cut -d: -f1)
    tail -c +$((at + 29)) "$1" | head -c 1 | od -An -tu1 | tr -d ' '
}
i=0
for c in none rle zips zip piz pxr24; do
    expect "compression $c"      0 '' '' -- render --size 40x36 --compression $c -j 2 -o "$imgdir/c-$c.exr"
    check  "header says $c"      test "$(compression_of "$imgdir/c-$c.exr")" = $i
    i=$((i + 1))
done
check  "compression changes size" test "$(wc -c <"$imgdir/c-none.exr")" -gt "$(wc -c <"$imgdir/c-zip.exr")"
expect "zip on one thread"       0 '' '' -- render --size 40x36 --compression zip -j 1 -o "$imgdir/c-zi1.exr"
# the files differ only in the command line's "-j 2" / "-j 1" and "c-zip" / "c-zi1"
check  "threads do not change the file" test "$(cmp -l "$imgdir/c-zip.exr" "$imgdir/c-zi1.exr" | wc -l)" = 2
expect "bad compression"         2 '' 'error: render: --compression dwaa: expected none|rle|zips|zip|piz|pxr24' -- render --compression dwaa -o "$imgdir/x.exr"
# --tier: the fast tier renders; a tier for a scene the kernel lacks says why; shade's bits8,
# which computed what bits12 does, is no tier of it
expect "tier bits12"             0 '' '' -- render --size 16x16 --tier bits12 -o "$imgdir/t12.exr"
expect "bad tier"                2 '' 'error: render: --tier u1: expected accurate or bits12' -- render --tier u1 -o "$imgdir/x.exr"
expect "no tier bits8"           2 '' 'error: render: --tier bits8: expected accurate or bits12' -- render --tier bits8 -o "$imgdir/x.exr"
expect "tier needs the kernel"   2 '' 'error: render: --tier bits12: the shading kernel does not compute this scene: model ads: the legacy fixed-function models are not covered by the batch kernels (they compute the BRDF models)' -- render --tier bits12 --brdf ads -o "$imgdir/x.exr"
expect "tier needs highp"        2 '' 'error: render: --tier bits12: the shading kernel computes highp, not -p double' -- render --tier bits12 -p double -o "$imgdir/x.exr"
check  "nothing written on tier errors" test ! -e "$imgdir/x.exr"
