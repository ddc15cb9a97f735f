# shadecalc sweep: rows against `shadecalc eval` and `shadecalc shade` at the same points, the
# header, the grid's order, the same bytes on 1 and 4 threads, SVG plots read by an XML parser,
# presets, atomic files, a closed pipe, and the errors.
. tests/e2e/lib.sh

sweep() { "$SHADECALC" sweep "$@" 2>"$e2e_tmp/err"; }

expect "header and rows" 0 'x,value
0,0
0.5,0.25
1,1' '' -- sweep --var x=0:1:3 'x * x'
expect "first variable fastest" 0 'a,b,value
1,10,11
2,10,12
1,20,21
2,20,22' '' -- sweep --var a=1,2 --var b=10,20 'a + b'
expect "vector columns" 0 '~x,result_x,result_y,result_z' '' -- sweep --var x=1,2 'vec3(x, 2.0, 3.0)'
expect "shading columns" 0 '~r,result_r,result_g,result_b' '' -- sweep --var r=1 --light 'point pos=0,0,$r'
expect "tsv" 0 'x	value
2	4' '' -- sweep -f tsv --var x=2 'x * x'
expect "log spacing" 0 'm,value
1,1
10,10
100,100
1000,1000' '' -- sweep --var m=1:1000:4 --log 'm'
expect "log of one variable" 0 '~10,0.5' '' -- sweep --var m=1:100:3 --var t=0,0.5 --log=m 'm*t'
sweep -f jsonl --var x=0:1:5 'vec2(x, 1.0 / x)' >"$e2e_tmp/rows.jsonl"
verdict "jsonl is JSON" python3 -c '
import json, sys
rows = [json.loads(line) for line in open(sys.argv[1])]
assert len(rows) == 5 and rows[0]["result_y"] == "inf" and rows[4]["result_x"] == 1, rows' \
    "$e2e_tmp/rows.jsonl"

# every row against `shadecalc eval` of the same expression with the value written in (as a
# float: a value printed as `1` is an int literal in GLSL ES)
sweep --var x=0:1:7 --var y=0.5,3 'pow(x, 32.0) * y + sin(x)' | tail -n +2 >"$e2e_tmp/rows.csv"
same=1
while IFS=, read -r x y value; do
    [ "$("$SHADECALC" eval "pow(float($x), 32.0) * float($y) + sin(float($x))")" = "$value" ] || same=0
done <"$e2e_tmp/rows.csv"
verdict "rows equal eval" test $same = 1
sweep -p mediump --var x=0.1:10:5 'exp2(x)' | tail -n +2 >"$e2e_tmp/rows.csv"
same=1
while IFS=, read -r x value; do
    [ "$("$SHADECALC" eval -p mediump "exp2(float($x))")" = "$value" ] || same=0
done <"$e2e_tmp/rows.csv"
verdict "mediump rows equal eval" test $same = 1
# the rows run in blocks, a loop whose trip count depends on the row under a mask: each row as
# `eval` computes it alone
loop='float s = 1.0; for (int i = 0; i < int(x); i++) { if (s > 4.0) break; s = s * 1.5 + x; } s'
sweep --var x=0:9:37 "$loop" | tail -n +2 >"$e2e_tmp/rows.csv"
same=1
while IFS=, read -r x value; do
    [ "$("$SHADECALC" eval -D "x=float($x)" "$loop")" = "$value" ] || same=0
done <"$e2e_tmp/rows.csv"
verdict "divergent rows equal eval" test $same = 1
expect "runtime error names the row" 1 'x,value
0,0
0.25,0.25
0.5,0.5' "error: sweep: row 4: column 20: index 3 is out of range 0..2" -- sweep --var x=0:1:5 'vec3 v = vec3(x); v[int(x * 4.0)]'
expect "GLSL ES: no int beside a float" 2 '' "~sweep: 'x * 2': column 3: operator '*': operands float and int do not match (GLSL ES converts nothing implicitly: write a float literal (1.0, not 1)" -- sweep --var x=0:1:3 'x * 2'
expect "an int result" 2 '' "error: sweep: 'int(x)' is of type int: the result columns are floats (convert it: float(...), vec2(...) ...)" -- sweep --var x=0:1:3 'int(x)'

# $r in a light spec against `shadecalc shade` with the value written in (the issue's example)
light='point pos=0,0,$r I=1 atten=window rstart=1 rend=10'
sweep --var r=0:12:13 --light "$light" --brdf 'blinn-phong m=8' --v 0,0.6,0.8 |
    tail -n +2 >"$e2e_tmp/rows.csv"
same=1
while IFS=, read -r r cr cg cb; do
    want=$("$SHADECALC" shade -f csv --light "point pos=0,0,$r I=1 atten=window rstart=1 rend=10" \
        --brdf 'blinn-phong m=8' --v 0,0.6,0.8 | tail -n 1)
    [ "$want" = "$cr,$cg,$cb" ] || same=0
done <"$e2e_tmp/rows.csv"
verdict "rows equal shade" test $same = 1
verdict "window reaches 0 at r_end" test "$(sed -n 11p "$e2e_tmp/rows.csv")" = '10,0,0,0'

# BRDF without lights: f(l, v) with l = dir(theta_i, 0), v = dir(theta_o, 0) (docs/formulas.md §1)
# against shade with a unit directional light along l: L_o = f cos(theta_i)
sweep -p double --var theta_i=0,30,60 --var theta_o=-50,20 --brdf 'cook-torrance alpha=0.3' |
    tail -n +2 >"$e2e_tmp/rows.csv"
same=1
while IFS=, read -r ti to fr fg fb; do
    l=$(awk -v t="$ti" 'BEGIN { r = t * atan2(0, -1) / 180; printf "%.17g,0,%.17g", sin(r), cos(r) }')
    v=$(awk -v t="$to" 'BEGIN { r = t * atan2(0, -1) / 180; printf "%.17g,0,%.17g", sin(r), cos(r) }')
    L=$("$SHADECALC" shade -p double -f csv --light "directional dir=$l" \
        --brdf 'cook-torrance alpha=0.3' --v "$v" | tail -n 1)
    awk -v L="$L" -v f="$fr,$fg,$fb" -v t="$ti" 'BEGIN {
        split(L, a, ","); split(f, b, ","); c = cos(t * atan2(0, -1) / 180)
        for (k = 1; k <= 3; k++) { d = a[k] - b[k] * c; if (d < 0) d = -d
            if (d > 1e-12 * (a[k] < 0 ? -a[k] : a[k]) + 1e-300) exit 1 } }' || same=0
done <"$e2e_tmp/rows.csv"
verdict "brdf rows equal shade / cos" test $same = 1
verdict "brdf rows" test "$(wc -l <"$e2e_tmp/rows.csv")" = 6

# theta_i moves a directional light; the result equals shade with that direction
expect "theta_i moves the light" 0 "~30,90,$("$SHADECALC" shade -f csv --light 'directional dir=0,0.5,0.8660254037844386' --brdf lambert | tail -n 1)" '' \
    -- sweep --var theta_i=30 --var phi_i=90 --light 'directional dir=1,0,0' --brdf lambert -f csv
# half-vector angles: plain Blinn-Phong with m = 1 and no diffuse is cos(theta_h) at phi_d = 90°
sweep -p double --var theta_h=0:80:9 --var theta_d=0,40,85 --brdf 'blinn-phong form=plain diff=0 spec=1 m=1' |
    tail -n +2 >"$e2e_tmp/rows.csv"
verdict "theta_h, theta_d" awk -F, '{ w = cos($1 * atan2(0, -1) / 180); d = $3 - w; if (d < 0) d = -d
                                      if (d > 1e-12) bad = 1 } END { exit bad || NR != 27 }' "$e2e_tmp/rows.csv"

# the same bytes on one thread and on four, also when rows are expensive and few
sweep -j 1 --var x=0:1:20001 --var y=0,2,5 'vec2(pow(x, y), sin(x * y))' >"$e2e_tmp/one.csv"
sweep -j 4 --var x=0:1:20001 --var y=0,2,5 'vec2(pow(x, y), sin(x * y))' >"$e2e_tmp/four.csv"
verdict "1 and 4 threads: same bytes" cmp -s "$e2e_tmp/one.csv" "$e2e_tmp/four.csv"
verdict "all rows" test "$(wc -l <"$e2e_tmp/four.csv")" = 60004
sweep -j 1 --var theta_o=-90:90:37 --var theta_i=0,45 --brdf 'ward alpha=0.2' >"$e2e_tmp/one.csv"
sweep -j 3 --var theta_o=-90:90:37 --var theta_i=0,45 --brdf 'ward alpha=0.2' >"$e2e_tmp/four.csv"
verdict "shading on 1 and 3 threads" cmp -s "$e2e_tmp/one.csv" "$e2e_tmp/four.csv"

# SVG plots, read by an XML parser: one series per (column, value of the second variable)
svg_points() { # FILE: "series:points ..." of every series
    python3 -c '
import sys, xml.etree.ElementTree as ET
ns = {"s": "http://www.w3.org/2000/svg"}
root = ET.parse(sys.argv[1]).getroot()
out = []
for g in root.iter("{http://www.w3.org/2000/svg}g"):
    if g.get("class") == "series":
        n = sum(len(p.get("points").split()) for p in g.findall("s:polyline", ns))
        out.append("%s:%d" % (g.get("data-label"), n))
print(" ".join(out))' "$1"
}
expect "plot" 0 '' '' -- sweep --var x=0:1:101 --var k=1,2 --plot "$e2e_tmp/p.svg" 'vec2(pow(x, k), x)'
verdict "plot series and points" test "$(svg_points "$e2e_tmp/p.svg")" = \
    'x, k=1:101 x, k=2:101 y, k=1:101 y, k=2:101'
expect "plot and table" 0 '' '' -- sweep --var x=0:1:11 --plot "$e2e_tmp/q.svg" -o "$e2e_tmp/q.csv" 'x'
verdict "table beside the plot" test "$(wc -l <"$e2e_tmp/q.csv")" = 12
verdict "one unlabelled curve" test "$(svg_points "$e2e_tmp/q.svg")" = ':11'
expect "grey rgb is one curve" 0 '' '' -- sweep --var theta_o=-90:90:61 --var theta_i=0,30 --brdf 'phong m=20' --polar --plot "$e2e_tmp/lobe.svg"
# the two points on the horizon (theta_o = ±90) are not drawn in a polar plot
verdict "polar series" test "$(svg_points "$e2e_tmp/lobe.svg")" = 'theta_i=0:59 theta_i=30:59'
verdict "axis labels" python3 -c '
import sys, xml.etree.ElementTree as ET
texts = {t.get("class"): t.text for t in ET.parse(sys.argv[1]).getroot().iter("{http://www.w3.org/2000/svg}text")}
assert texts["xlabel"] == "theta_o (degrees)" and texts["ylabel"] == "f(l, v) [1/sr]", texts
assert texts["title"] == "phong m=20", texts' "$e2e_tmp/lobe.svg"
expect "labels and log axes" 0 '' '' -- sweep --var m=1:1000:31 --log --title 'T <&>' --xlabel X --ylabel Y --ylog --plot "$e2e_tmp/log.svg" 'pow(m, 2.0)'
verdict "escaped title" python3 -c '
import sys, xml.etree.ElementTree as ET
t = [e.text for e in ET.parse(sys.argv[1]).getroot().iter("{http://www.w3.org/2000/svg}text") if e.get("class") == "title"]
assert t == ["T <&>"], t' "$e2e_tmp/log.svg"

# presets: the lecture's figures
for p in attenuation spot lobe albedo; do
    expect "preset $p" 0 '' '' -- sweep --preset "$p" --plot "$e2e_tmp/$p.svg" -o "$e2e_tmp/$p.csv"
done
verdict "attenuation curves" test "$(svg_points "$e2e_tmp/attenuation.svg")" = \
    'none:241 inverse-square 1/r^2:241 clq 1, 0.05, 0.02:241 window 2..10:241 pixar fmax=2 fc=1 rc=1:241 windowed rmax=10:241'
verdict "attenuation header" test "$(head -n 1 "$e2e_tmp/attenuation.csv")" = 'r,none,inverse_square,clq,window,pixar,windowed'
# docs/formulas.md §3 worked examples: window at r = 4 is 0.75, pixar at r = 2 is 0.25, clq at 5 is 1/1.75
verdict "attenuation values" awk -F, '$1 == 4 { w = $5 } $1 == 2 { p = $6 } $1 == 5 { c = $4 }
    END { exit !(w == 0.75 && p == 0.25 && c == 0.5714286) }' "$e2e_tmp/attenuation.csv"
verdict "spot header" test "$(head -n 1 "$e2e_tmp/spot.csv")" = 'theta_s,opengl,directx,smoothstep'
verdict "lobe curves" test "$(svg_points "$e2e_tmp/lobe.svg")" = 'theta_i=0:179 theta_i=30:179 theta_i=60:179'
verdict "albedo of lambert is 1" awk -F, 'NR > 1 { d = $2 - 1; if (d < 0) d = -d; if (d > 1e-9) bad = 1 } END { exit bad || NR != 91 }' "$e2e_tmp/albedo.csv"
expect "preset variable replaced" 0 '~r,none' '' -- sweep --preset attenuation --var r=0:1:3
expect "albedo of given brdfs" 0 '~theta_i,brdf1,brdf2' '' -- sweep --preset albedo --var theta_i=0 --brdf lambert --brdf 'lambert diff=0.5'

# images: width x height of the two variables (pixel values are read back in test_sweep.c)
expect "image" 0 '' '' -- sweep --var theta_h=0:90:31 --var theta_d=0:90:16 --brdf 'cook-torrance alpha=0.2' --image "$e2e_tmp/slice.exr" --exr-type half
verdict "exr magic and ranges" sh -c "head -c 4 '$e2e_tmp/slice.exr' | od -An -tx1 | grep -q '76 2f 31 01' &&
    grep -q -a 'theta_d=0:90:16' '$e2e_tmp/slice.exr' && grep -q -a \"shadecalc sweep --var theta_h=0:90:31\" '$e2e_tmp/slice.exr'"

# files are atomic: a failure leaves no file, and an older file intact
echo old >"$e2e_tmp/keep.csv"
cp "$e2e_tmp/p.svg" "$e2e_tmp/keep.svg"
expect "failing row" 2 '' "error: sweep: row 4: 'point pos=0,0,1 atten=window rstart=3 rend=2': light point: rstart=3 rend=2: window needs 0 <= rstart <= rend" \
    -- sweep --var e=5:2:4 --light 'point pos=0,0,1 atten=window rstart=3 rend=$e' -o "$e2e_tmp/keep.csv" --plot "$e2e_tmp/keep.svg"
verdict "old table intact" test "$(cat "$e2e_tmp/keep.csv")" = old
verdict "old plot intact" cmp -s "$e2e_tmp/p.svg" "$e2e_tmp/keep.svg"
verdict "no temporaries" test -z "$(find "$e2e_tmp" -name '.*.tmp')"
expect "missing directory" 1 '' "~$e2e_tmp/none/p.svg" -- sweep --var x=0:1:3 --plot "$e2e_tmp/none/p.svg" x
verdict "nothing written" test ! -e "$e2e_tmp/none"
expect "table into missing directory" 1 '' "~$e2e_tmp/none/t.csv" -- sweep --var x=0:1:3 -o "$e2e_tmp/none/t.csv" x

# a closed pipe stops the sweep quietly
("$SHADECALC" sweep --var x=0:1:10000000 'x' 2>"$e2e_tmp/pipe.err"; echo $? >"$e2e_tmp/pipe.status") | head -n 2 >/dev/null
verdict "closed pipe: quiet" test ! -s "$e2e_tmp/pipe.err"
verdict "closed pipe: status 1" test "$(cat "$e2e_tmp/pipe.status")" = 1

# errors name the input
expect "no subject"         2 '' "error: sweep: nothing to sweep: give an EXPR, --brdf SPEC, --light SPEC or --preset NAME (see 'shadecalc sweep --help')" -- sweep --var x=0:1:3
expect "bad var"            2 '' "error: sweep: --var x=0:1: expected NAME=START:STOP:COUNT (finite numbers, COUNT >= 1) or NAME=V1,V2,..." -- sweep --var x=0:1 x
expect "duplicate var"      2 '' '~x: given twice' -- sweep --var x=0:1:3 --var x=1 x
expect "bad log"            2 '' "error: sweep: --log: x=0:1: geometric spacing needs ends of the same sign, not zero" -- sweep --var x=0:1:3 --log x
expect "log of nothing"     2 '' 'error: sweep: --log=y: no such variable' -- sweep --var x=1:2:3 --log=y x
expect "unknown variable"   2 '' "error: sweep: --light 'point pos=0,0,\$q': '\$q': unknown variable (give it with --var q=...)" -- sweep --var r=1 --light 'point pos=0,0,$q'
expect "no \$ in geometry"  2 '' '~$variables work in --light and --brdf specs only' -- sweep --var r=1 --light 'point pos=0,0,1' --v '0,0,$r'
expect "expression error"   2 '' "~sweep: 'pow(x)': column" -- sweep --var x=0:1:3 'pow(x)'
expect "expr and a light"   2 '' '~is evaluated on its own' -- sweep --var x=1 --light 'point pos=0,0,1' x
expect "unknown preset"     2 '' "error: sweep: unknown preset 'foo' (attenuation|spot|lobe|albedo|area-distance|area-roughness)" -- sweep --preset foo
expect "angles, no directional light" 2 '' '~there is none' -- sweep --var theta_i=0:90:3 --light 'point pos=0,0,1'
expect "both angle kinds"   2 '' '~not both' -- sweep --var theta_i=0 --var theta_h=0 --brdf lambert
expect "model without brdf" 2 '' '~give a --light to shade with it' -- sweep --var theta_i=0 --brdf opengl
expect "image of one var"   2 '' '~needs exactly two variables' -- sweep --var x=0:1:3 --image "$e2e_tmp/x.exr" x
expect "plot of three vars" 2 '' '~draws one or two variables' -- sweep --var x=0:1:3 --var y=1 --var z=1 --plot "$e2e_tmp/x.svg" x
expect "bad threads"        2 '' 'error: sweep: --threads 0: expected a whole number from 1 to 256' -- sweep -j 0 --var x=1 x
expect "bad format"         2 '' "error: sweep: unknown format 'xml' (csv, tsv, jsonl)" -- sweep -f xml --var x=1 x
expect "bad yrange"         2 '' 'error: sweep: --yrange 2:1: expected LO:HI with LO < HI' -- sweep --yrange 2:1 --var x=1 x
expect "too many rows"      2 '' 'error: sweep: the grid has more than 2^52 rows' -- sweep --var a=0:1:100000000 --var b=0:1:100000000 a
expect "stray argument"     2 '' "~unexpected argument 'y'" -- sweep --var x=1 x y
expect "help"               0 '~usage: shadecalc sweep' '' -- sweep --help

# a row whose value is beyond the precision is an error naming the key, not a NaN row (issue 11 §7);
# row 1 at l = v = n: 0.8/π + F0/(4πα²) = 0.57295780 (GGX D = 1/(πα²), G = 1)
expect "row beyond highp" 2 'a,r,g,b
0.1,0.57295775,0.57295775,0.57295775' "error: sweep: row 2: 'cook-torrance alpha=1e+39': alpha=1e+39: beyond the highp range (|x| <= 3.4028235e+38)" -- sweep --var a=0.1,1e39 --light 'directional dir=0,0,1' --brdf 'cook-torrance alpha=$a'

# --tier: shading rows by a plan of the batch kernel, within the tier's bound of the double path
# rows of numbers (CSV) within relative tolerance TOL of the reference rows
rows_within() {
    printf '%s\n' "$1" >"$e2e_tmp/want.csv"
    printf '%s\n' "$2" >"$e2e_tmp/got.csv"
    paste -d, "$e2e_tmp/want.csv" "$e2e_tmp/got.csv" | awk -F, -v tol="$3" '
        { n = NF / 2; for (i = 1; i <= n; i++) { d = $i - $(i + n); a = $i
          if (d < 0) d = -d; if (a < 0) a = -a; if (d > tol * a) bad = 1 } }
        END { exit bad }'
}
tier_run() { "$SHADECALC" sweep --var theta_o=0:80:9 --light 'point pos=0,1,3 I=10' --light 'spot pos=1,0,3 dir=0,0,-1 I=20 spot=smoothstep inner=20 outer=50' --brdf 'ward ax=0.3 ay=0.3 spec=0.3' "$@" | tail -n +2; }
tier_ref=$(tier_run -p double)
verdict "tier bits12 near double"   rows_within "$tier_ref" "$(tier_run --tier bits12)" 5e-4
verdict "tier accurate near double" rows_within "$tier_ref" "$(tier_run --tier accurate)" 1e-5
verdict "tier rows differ from highp" test "$(tier_run --tier bits12)" != "$(tier_run)"
expect "tier: one scene"   2 '' 'error: sweep: --tier bits12: $variables in --light/--brdf change the scene from row to row' -- sweep --var m=1:3:3 --light 'point pos=0,0,3 I=10' --brdf 'blinn-phong m=$m' --tier bits12
expect "tier: moving l"    2 '' 'error: sweep: --tier bits12: theta_i/phi_i (or the half-vector angles) turn the directional lights row by row' -- sweep --var theta_i=0:80:3 --light 'directional dir=0,0,1' --tier bits12
expect "tier: highp"       2 '' 'error: sweep: --tier bits12: the batch kernels compute highp' -- sweep --var theta_o=0:80:3 --light 'point pos=0,0,3 I=10' -p mediump --tier bits12
expect "tier: legacy"      2 '' '~model ads: the legacy fixed-function models are not covered' -- sweep --var theta_o=0:80:3 --light 'point pos=0,0,3 I=10' --brdf ads --tier bits12
expect "tier: not an EXPR" 2 '' 'error: sweep: --tier bits12 applies to shading sweeps (--light), not to an EXPR' -- sweep --var x=0:1:3 'x*x' --tier bits12
expect "tier: unknown"     2 '' 'error: sweep: --tier u9: expected accurate or bits12' -- sweep --var theta_o=0:80:3 --light 'point pos=0,0,3 I=10' --tier u9
expect "tier: no bits8"    2 '' 'error: sweep: --tier bits8: expected accurate or bits12' -- sweep --var theta_o=0:80:3 --light 'point pos=0,0,3 I=10' --tier bits8
