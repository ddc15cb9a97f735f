# Area lights (docs/formulas.md §5): shade values against closed forms computed here, the spec
# errors naming their key, check --light's table and formats, the sweep presets.
. tests/e2e/lib.sh

pi=3.14159265358979323846
square='rect center=0,0,1 edge1=1,0,0 edge2=0,-1,0'
# the unit square at height 1: E = 0.752274688454 (n = +z), half of it for n tilted 60°
expect_close "unit square" 1e-10 "0.752274688454 0.752274688454 0.752274688454" -- \
    shade --light "$square" --brdf "lambert diff=$pi" --precision double
expect_close "unit square, n tilted 60" 1e-10 "0.376137344227 0.376137344227 0.376137344227" -- \
    shade --light "$square" --brdf "lambert diff=$pi" --precision double --n 0.8660254037844386,0,0.5
expect_close "square by size" 1e-10 "0.752274688454 0.752274688454 0.752274688454" -- \
    shade --light 'rect center=0,0,1 normal=0,0,-1 width=1 height=1' --brdf "lambert diff=$pi" --precision double
# sphere R = 0.5 at d = 2, 30° off the normal: E = π sin²σ cos θ = 0.170043690397
expect_close "ltc exact for lambert" 1e-10 "0.376137344227 0.376137344227 0.376137344227" -- \
    shade --light "$square method=ltc" --brdf "lambert diff=$pi" --precision double --n 0.8660254037844386,0,0.5
expect_close "sphere above the horizon" 1e-10 "0.170043690397 0.170043690397 0.170043690397" -- \
    shade --light 'sphere center=1,0,1.7320508075688772 radius=0.5' --brdf "lambert diff=$pi" --precision double
expect_close "point stand-in of the sphere" 1e-12 "0.170043690397 0.170043690397 0.170043690397" -- \
    shade --light 'sphere center=1,0,1.7320508075688772 radius=0.5 method=point' --brdf "lambert diff=$pi" --precision double
# disk R = 0.5 at h = 1 on its axis: E/π = R²/(R² + h²) = 0.2
expect_close "disk on its axis" 1e-10 "0.2 0.2 0.2" -- \
    shade --light 'disk center=0,0,1 normal=0,0,-1 radius=0.5' --brdf 'lambert diff=1' --precision double
expect_close "one-sided disk from behind" 0 "0 0 0" -- \
    shade --light 'disk center=0,0,1 normal=0,0,1 radius=0.5' --brdf 'lambert diff=1'
expect_close "inside a tube: c_diff L_e" 1e-12 "0.5 0.5 0.5" -- \
    shade --light 'tube p0=-1,0,0 p1=1,0,0 radius=0.5 L=2' --brdf 'lambert diff=0.25' --precision double
printf 'light %s\nbrdf lambert diff=%s\n' "$square" "$pi" >"$e2e_tmp/area.scene"
expect_close "scene file" 1e-10 "0.752274688454 0.752274688454 0.752274688454" -- \
    shade --scene "$e2e_tmp/area.scene" --precision double
# a sphere of radius 1 at distance d: E/π = 1/d²
verdict "sweep with \$var" sh -c "'$SHADECALC' sweep --var d=2,4 --light 'sphere center=0,0,\$d radius=1' \
    --brdf 'lambert diff=1' --precision double | awk -F, 'NR > 1 { e = \$2 * \$1 * \$1 - 1; bad += e > 1e-12 || e < -1e-12; n++ }
    END { exit bad || n != 2 }'"
expect "explain" 0 '~light 1 (rect, method=reference)' '' -- shade --explain --light "$square" --brdf lambert
verdict "json error estimate" sh -c "'$SHADECALC' shade -f json --explain --light '$square samples=8' --brdf lambert |
    python3 -c 'import json, sys; l = json.load(sys.stdin)[\"lights\"][0]; assert l[\"nodes\"] == 8 and 0 < l[\"error\"][0] < 1e-3, l'"
expect "render" 0 '' '' -- render --light 'sphere center=3,3,3 radius=1 method=representative-point' --brdf cook-torrance --size 16x16 -o "$e2e_tmp/area.exr"

# bad specs: exit 2, the key named
expect "negative radius" 2 '' 'error: light sphere: radius=-1: must be >= 0' -- shade --light 'sphere center=0,0,2 radius=-1'
expect "zero normal" 2 '' 'error: light disk: normal must not be the zero vector' -- shade --light 'disk center=0,0,1 normal=0,0,0 radius=1'
expect "degenerate rect" 2 '' 'error: light rect: edge1, edge2: a degenerate rectangle (zero or parallel edges)' -- shade --light 'rect center=0,0,1 edge1=1,0,0 edge2=2,0,0'
expect "zero width" 2 '' 'error: light rect: width=0 height=1: a degenerate rectangle (each must be > 0)' -- shade --light 'rect center=0,0,1 normal=0,0,-1 width=0 height=1'
expect "unknown method" 2 '' "error: light sphere: method=pont: expected reference|representative-point|point|ltc (did you mean 'point'?)" -- shade --light 'sphere center=0,0,2 radius=1 method=pont'
expect "method not for the shape" 2 '' 'error: light rect: method=representative-point: sphere and tube lights only' -- shade --light "$square method=representative-point"
expect "missing radius" 2 '' 'error: light tube: missing radius=R' -- shade --light 'tube p0=0,0,1 p1=1,0,1'
expect "two rect forms" 2 '' 'error: light rect: give edge1=, edge2= or normal=, width=, height=, not both' -- shade --light "$square width=1"
expect "samples range" 2 '' 'error: light sphere: samples=1: must be 2..512 (or 0: until tol)' -- shade --light 'sphere center=0,0,2 radius=1 samples=1'
expect "samples integer" 2 '' '~samples=2.5: expected an integer' -- shade --light 'sphere center=0,0,2 radius=1 samples=2.5'
expect "ltc and phong" 2 '' 'error: light 1: method=ltc: not for brdf phong as given (ltc takes lambert, or cook-torrance with D=ggx G=smith-correlated F=schlick|none and ax = ay)' -- shade --light "$square method=ltc" --brdf phong
expect "ltc and a sphere" 2 '' 'error: light sphere: method=ltc: disk and rect lights only' -- shade --light 'sphere center=0,0,2 radius=1 method=ltc'
expect "legacy model" 2 '' '~light 1: area lights need a BRDF' -- shade --light "$square" --brdf ads
expect "tol without reference" 0 '*' 'warning: light sphere: tol= has no effect with method=point' -- shade --light 'sphere center=0,0,2 radius=1 method=point tol=1e-3'

# check --light: one row per method that applies, in three formats
expect "check table" 0 '~method                 max_rel_error mean_rel_error  ns_per_eval  worst configuration' '' -- \
    check --light 'disk center=0,0,1 normal=0,0,-1 radius=1' --brdf lambert
# ltc is exact for Lambert: 1e-5 leaves room for the rounding of the closed form on slivers
# (3e-8 of a rect left above the horizon)
verdict "check rows of a rect" sh -c "'$SHADECALC' check --light '$square' --brdf lambert | awk '
    NR > 4 { m = m \" \" \$1 } \$1 == \"ltc\" { exact = \$2 < 1e-5 } END { exit !(exact && m == \" reference point ltc\") }'"
verdict "check rows" sh -c "'$SHADECALC' check --light 'sphere center=0,0,2 radius=1' --brdf lambert | awk '
    NR == 3 { ok = \$1 == 80 } NR > 4 { m = m \" \" \$1 } END { exit !(ok && m == \" reference representative-point point\") }'"
# Lambert and a sphere: the representative point is exact where the sphere is above the horizon
verdict "check csv" sh -c "'$SHADECALC' check --light 'sphere center=0,0,2 radius=1' --brdf lambert -f csv | awk -F, '
    NR == 1 { ok = \$0 == \"light,brdf,method,configs,max_rel_error,mean_rel_error,ns_per_eval,worst\" }
    NR > 1 { n++ } END { exit !(ok && n == 3) }'"
verdict "check json" sh -c "'$SHADECALC' check --light 'tube p0=0,0,2 p1=1,0,2 radius=0.5' --brdf lambert -f json |
    python3 -c 'import json, sys; d = json.load(sys.stdin); assert d[\"configs\"] == 80 and [m[\"method\"] for m in d[\"methods\"]] == [\"reference\", \"representative-point\", \"point\"], d'"
expect "check: not an area light" 2 '' 'error: check: --light point pos=0,0,1: an area light (sphere, tube, disk, rect)' -- check --light 'point pos=0,0,1' --brdf lambert
expect "check: one brdf" 2 '' 'error: check: --light takes one --brdf' -- check --light "$square" --brdf lambert --brdf phong
expect "check: json needs --light" 2 '' 'error: check: --format json is for --light (area lights); the albedo table is table or csv' -- check --brdf lambert -f json

# the presets: one column per curve, errors that fall with the distance
expect "preset area-distance" 0 '' '' -- sweep --preset area-distance --var ratio=2,8 -o "$e2e_tmp/ad.csv" --plot "$e2e_tmp/ad.svg"
verdict "area-distance header" test "$(head -n 1 "$e2e_tmp/ad.csv")" = \
    'ratio,sphere_representative,sphere_point,tube_representative,tube_point,disk_point,disk_ltc,rect_point,rect_ltc'
verdict "point error falls with the distance" awk -F, 'NR == 2 { a = $3 } NR == 3 { b = $3 } END { exit !(b < a / 4) }' "$e2e_tmp/ad.csv"
verdict "area-distance svg" python3 -c 'import sys, xml.etree.ElementTree as ET; ET.parse(sys.argv[1])' "$e2e_tmp/ad.svg"
expect "preset area-roughness" 0 '~alpha,sphere_representative' '' -- sweep --preset area-roughness --var alpha=0.2,0.5

# The batch kernels' plans take area lights by their approximations (not method=reference):
# sweep --tier rows against the double approximation (-p double), within the area rows' bounds
# (absolute: 2^-15 x L_e (c_diff + c_spec) = 1.2e-4 here, for L_e 2 and c_diff + c_spec 2)
rows_close() { # WANT GOT TOL: every number within TOL (absolute)
    printf '%s\n' "$1" >"$e2e_tmp/want.csv"
    printf '%s\n' "$2" >"$e2e_tmp/got.csv"
    [ -s "$e2e_tmp/got.csv" ] && paste -d, "$e2e_tmp/want.csv" "$e2e_tmp/got.csv" | awk -F, -v tol="$3" '
        { n = NF / 2; for (i = 1; i <= n; i++) { d = $i - $(i + n); if (d < 0) d = -d
          if (d > tol || $(i + n) == "") bad = 1 } }
        END { exit bad }'
}
area_rows() { # LIGHT [OPTIONS]
    l=$1; shift
    "$SHADECALC" sweep --var theta_o=0:80:9 --light "$l" --brdf 'cook-torrance D=ggx G=smith-correlated F=schlick alpha=0.3' "$@" | tail -n +2
}
for light in 'sphere center=0,1,3 radius=0.5 L=2 method=representative-point' \
    'tube p0=-1,0,3 p1=1,1,3 radius=0.2 L=2 method=representative-point' \
    'disk center=0,0,3 normal=0,0,-1 radius=1 L=2 method=ltc' \
    'rect center=0.5,0,2 edge1=0,1,0 edge2=1,0,0 L=2 method=ltc' \
    'rect center=0.5,0,2 edge1=0,1,0 edge2=1,0,0 L=2 method=point'; do
    want=$(area_rows "$light" -p double)
    verdict "sweep --tier accurate: ${light%% *} ${light##* }" rows_close "$want" "$(area_rows "$light" --tier accurate)" 1.2e-4
    verdict "sweep --tier bits12: ${light%% *} ${light##* }" rows_close "$want" "$(area_rows "$light" --tier bits12)" 2e-3
done
expect "sweep --tier: method=reference" 2 '' '~light 1: sphere method=reference is not covered by the batch kernels (shade and check evaluate it' -- sweep --var theta_o=0:80:9 --light 'sphere center=0,1,3 radius=0.5' --tier accurate
expect "render --tier: ltc" 0 '' '' -- render --light 'rect center=0,0,4 edge1=2,0,0 edge2=0,2,0 two-sided=1 L=3 method=ltc' --brdf cook-torrance --size 16x16 --tier accurate -o "$e2e_tmp/ltc.exr"
expect "render --tier: reference refused" 2 '' '~method=reference is not covered by the batch kernels' -- render --light 'sphere center=3,3,3 radius=1' --size 16x16 --tier bits12 -o "$e2e_tmp/ref.exr"
