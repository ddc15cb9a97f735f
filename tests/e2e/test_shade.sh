# shadecalc shade: values against the reference's worked examples, the spec grammar's errors,
# scene files, output formats.
. tests/e2e/lib.sh

# Lambert ρ = 0.8 under a unit directional light along n: 0.8/π (docs/formulas.md §6.1)
expect_close "lambert" 1e-11 '0.254647908947 0.254647908947 0.254647908947' -- shade -p double --light 'directional dir=0,0,1' --brdf 'lambert diff=0.8'
# docs/formulas.md §6.8: the OpenGL worked example, non-local viewer
expect_close "opengl worked example" 1e-11 '0.570958041479 0.346991760775 0.223025480071' -- shade -p double --light 'spot pos=1,3,0 dir=0,-1,-1 atten=clq sc=1 sl=0.05 sq=0.02 cutoff=30 exp=10 amb=0.1' --brdf 'opengl emission=0.1,0,0 amb=0.2 diff=0.8,0.5,0.2 spec=0.5 m=20' --ambient 0.2 --p 1,0,-4 --eye 0,0,0
expect_close "opengl local viewer" 1e-11 '0.554565045793 0.330598765089 0.206632484385' -- shade -p double --light 'spot pos=1,3,0 dir=0,-1,-1 atten=clq sc=1 sl=0.05 sq=0.02 cutoff=30 exp=10 amb=0.1' --brdf 'opengl emission=0.1,0,0 amb=0.2 diff=0.8,0.5,0.2 spec=0.5 m=20 local-viewer=1' --ambient 0.2 --p 1,0,-4 --eye 0,0,0
expect_close "cook-torrance l=v=n" 1e-11 '0.0127323954474 0.0127323954474 0.0127323954474' -- shade -p double --light 'directional dir=0,0,1' --brdf 'cook-torrance diff=0 f0=0.04 alpha=0.5'
expect_close "perceptual roughness" 1e-11 '0.0127323954474 0.0127323954474 0.0127323954474' -- shade -p double --light 'directional dir=0,0,1' --brdf 'cook-torrance diff=0 f0=0.04 perceptual=0.7071067811865476'
expect "csv header"              0 'r,g,b
0.2546479,0.2546479,0.2546479' '' -- shade -f csv --light 'directional dir=0,0,1' --brdf 'lambert diff=0.8'
expect "json"                    0 '{"precision": "highp", "L": [0.2546479, 0.2546479, 0.2546479]}' '' -- shade -f json --light 'directional dir=0,0,1' --brdf 'lambert diff=0.8'
expect "explain"                 0 '~f_d = 0.0625  spot = 1  cos theta_s = 1  E_L = (3.125, 3.125, 3.125)' '' -- shade --explain --light 'spot pos=0,4,0 dir=0,-1,0 I=50 spot=directx inner=20 outer=30 exp=1' --brdf 'cook-torrance diff=0.5,0.1,0.1 f0=0.04 alpha=0.3 D=ggx G=smith F=schlick' --n 0,1,0 --v 0,1,1
expect "explain shows D G F"     0 '~D = 0.5747062  G = 0.9784589' '' -- shade --explain --light 'spot pos=0,4,0 dir=0,-1,0 I=50 spot=directx inner=20 outer=30 exp=1' --brdf 'cook-torrance diff=0.5,0.1,0.1 f0=0.04 alpha=0.3 D=ggx G=smith F=schlick' --n 0,1,0 --v 0,1,1
expect "two lights add"          0 '0.5092958 0.5092958 0.5092958' '' -- shade --light 'directional dir=0,0,1' --light 'directional dir=0,0,1' --brdf 'lambert diff=0.8'
expect "mediump"                 0 '0.2546 0.2546 0.2546' '' -- shade -p mediump --light 'directional dir=0,0,1' --brdf 'lambert diff=0.8'

scene=$e2e_tmp/scene.txt
printf '# a scene\nlight directional dir=0,0,1\n\nbrdf lambert diff=0.8\nambient 0\n' > "$scene"
expect "scene file"              0 '0.2546479 0.2546479 0.2546479' '' -- shade --scene "$scene"
expect "options add lights"      0 '0.5092958 0.5092958 0.5092958' '' -- shade --scene "$scene" --light 'directional dir=0,0,1'
expect "options override brdf"   0 '0.31830987 0.31830987 0.31830987' '' -- shade --scene "$scene" --brdf 'lambert diff=1'
printf 'light point pos=1,2\n' > "$e2e_tmp/bad.txt"
expect "scene file error line"   2 '' "error: $e2e_tmp/bad.txt:1: light point: pos=1,2: expected a point X,Y,Z" -- shade --scene "$e2e_tmp/bad.txt"
expect "missing scene file"      1 '' "error: $e2e_tmp/none.txt: No such file or directory" -- shade --scene "$e2e_tmp/none.txt"
# what is read from a scene file is bounded: /dev/zero ends at once, not after 32 GB
expect "/dev/zero as scene file"  2 '' 'error: /dev/zero:1: longer than 65536 bytes' -- shade --scene /dev/zero
printf 'light directional dir=0,0,1\0 I=2\n' >"$e2e_tmp/nul.txt"
expect "NUL byte in a scene file" 2 '' "error: $e2e_tmp/nul.txt:1: contains a NUL byte" -- shade --scene "$e2e_tmp/nul.txt"
expect "directory as scene file"  1 '' "error: $e2e_tmp: Is a directory" -- shade --scene "$e2e_tmp"
yes '# a comment line' | head -n 1000000 >"$e2e_tmp/long.txt" # 17 bytes a line: 986896 passes 16 MiB
expect "scene file over 16 MiB"   2 '' "error: $e2e_tmp/long.txt:986896: the input is longer than 16777216 bytes" -- shade --scene "$e2e_tmp/long.txt"
rm -f "$e2e_tmp/long.txt"

# errors name the item and the valid range
expect "opengl cutoff 120"       2 '' 'error: light spot: cutoff=120: spot=opengl takes 0..90 or 180' -- shade --light 'spot pos=0,4,0 dir=0,-1,0 spot=opengl cutoff=120'
expect "inner > outer"           2 '' 'error: light spot: inner=40 > outer=30: the inner cone must not exceed the outer' -- shade --light 'spot pos=0,4,0 dir=0,-1,0 spot=directx inner=40 outer=30'
expect "d3d9 full angles"        2 '' 'error: light spot: inner=40 > outer=30: the inner cone must not exceed the outer' -- shade --light 'spot pos=0,4,0 dir=0,-1,0 spot=directx theta=80 phi=60'
expect "fc > fmax"               2 '' 'error: light point: fc=2 fmax=1: pixar needs 0 < fc <= fmax' -- shade --light 'point pos=0,4,0 atten=pixar fmax=1 fc=2 rc=1 se=1'
expect "missing pos"             2 '' 'error: light point: missing pos=X,Y,Z' -- shade --light point
expect "unknown light kind"      2 '' "error: light: unknown kind 'lamp' (directional|point|spot|sphere|tube|disk|rect)" -- shade --light 'lamp pos=1,2,3'
expect "unknown key"             2 '' "error: light point: unknown key 'foo'" -- shade --light 'point pos=1,2,3 foo=1'
expect "key of another kind"     2 '' "error: light point: unknown key 'cutoff' (a key of other kinds)" -- shade --light 'point pos=1,2,3 cutoff=10'
expect "not key=value"           2 '' "error: light point: 'pos': expected key=value" -- shade --light 'point pos'
expect "zero direction"          2 '' 'error: light directional: dir must not be the zero vector' -- shade --light 'directional dir=0,0,0'
expect "negative roughness"      2 '' 'error: brdf cook-torrance: alpha=-0.1: must be >= 0 and finite' -- shade --light 'directional dir=0,0,1' --brdf 'cook-torrance alpha=-0.1'
expect "anisotropic no tangent"  2 '' 'error: brdf ward: anisotropic roughness (ax=0.1 ay=0.3) needs --tangent X,Y,Z' -- shade --light 'directional dir=0,0,1' --brdf 'ward ax=0.1 ay=0.3'
expect "anisotropic tangent"     0 '*' '' -- shade --light 'directional dir=0,1,1' --brdf 'ward ax=0.1 ay=0.3' --tangent 1,0,0
expect "zero normal"             2 '' 'error: --n 0,0,0: must not be the zero vector' -- shade --light 'directional dir=0,0,1' --n 0,0,0
expect "bad form"                2 '' 'error: brdf phong: form=weird: expected original|modified|normalized' -- shade --light 'directional dir=0,0,1' --brdf 'phong form=weird'
expect "bad enum"                2 '' 'error: brdf cook-torrance: D=foo: expected beckmann|ggx' -- shade --light 'directional dir=0,0,1' --brdf 'cook-torrance D=foo'
expect "unknown brdf"            2 '' "error: brdf: unknown kind 'torrance' (lambert|phong|blinn-phong|ward|oren-nayar|cook-torrance|ads|opengl|direct3d9)" -- shade --light 'directional dir=0,0,1' --brdf torrance
expect "no light"                2 '' "error: shade: no light: give --light SPEC (see 'shadecalc shade --help')" -- shade
expect "bad vector option"       2 '' 'error: --v 1,2: expected three numbers X,Y,Z' -- shade --light 'directional dir=0,0,1' --v 1,2
expect "stray argument"          2 '' "error: shade: unexpected argument 'lambert' (specs go after --light or --brdf)" -- shade --light 'directional dir=0,0,1' lambert
expect "explain csv"             2 '' 'error: shade: --explain prints text or json, not csv' -- shade --light 'directional dir=0,0,1' --explain -f csv
expect "help"                    0 '~usage: shadecalc shade' '' -- shade --help

# docs/formulas.md §6.8: the same light made directional (0,3,4) with cutoff 180; separate specular
expect_close "opengl directional"  1e-11 '0.97433922005 0.63433922005 0.39433922005' -- shade -p double --light 'directional dir=0,3,4 amb=0.1' --brdf 'opengl emission=0.1,0,0 amb=0.2 diff=0.8,0.5,0.2 spec=0.5 m=20' --ambient 0.2 --p 1,0,-4 --eye 0,0,0
# docs/formulas.md §6.6: GGX + height-correlated Smith + exact Fresnel at l = dir(60,0), v = dir(30,200):
# f = 0.0256271923424, times cos θ_i = 0.5
expect_close "ggx general case"    1e-10 '0.0128135961712 0.0128135961712 0.0128135961712' -- shade -p double --light 'directional dir=0.8660254037844386,0,0.5' --brdf 'cook-torrance diff=0 alpha=0.3 F=exact ior=1.5' --v -0.46984631039295416,-0.17101007166283433,0.8660254037844387 --tangent 1,0,0

# values beyond the precision's range (issue 11 §7): rejected naming the key, never NaN
expect "I beyond highp"          2 '' 'error: light 1: I=1e+39: beyond the highp range (|x| <= 3.4028235e+38)' -- shade --light 'directional dir=1,0,0 I=1e39' --brdf 'blinn-phong m=32' --n 0,1,0 --v 0,1,1
expect "I beyond mediump"        2 '' 'error: light 1: I=70000: beyond the mediump range (|x| <= 65504)' -- shade -p mediump --light 'directional dir=1,0,0 I=70000' --brdf 'blinn-phong m=32' --n 0,1,0 --v 0,1,1
expect "alpha beyond highp"      2 '' 'error: alpha=1e+39: beyond the highp range (|x| <= 3.4028235e+38)' -- shade --light 'directional dir=0,0,1' --brdf 'cook-torrance alpha=1e39'
expect "point beyond highp"      2 '' 'error: --p=1e+39: beyond the highp range (|x| <= 3.4028235e+38)' -- shade --light 'directional dir=0,0,1' --p 1e39,0,0
expect "double takes 1e39"       0 '0 0 0' '' -- shade -p double --light 'directional dir=1,0,0 I=1e39' --brdf 'blinn-phong m=32' --n 0,1,0 --v 0,1,1
# E = 3e38/(1e-2)² overflows highp: inf and a warning where the light reaches, 0 where it does not
expect "overflow is inf"         0 'inf inf inf' 'warning: shade: L_o overflows the highp range: inf' -- shade --light 'point pos=0,0,1e-2 I=3e38' --brdf 'blinn-phong'
expect "unlit overflow is 0"     0 '0 0 0' '' -- shade --light 'point pos=0,0,-1e-2 I=3e38' --brdf 'blinn-phong'
# highp: r² = 2e40 overflows, 1/r² does not: E = 1e38/2e40 = 0.005, times cos θ_i/π·0.8
expect_close "far light"         1e-5 '0.000900316316 0.000900316316 0.000900316316' -- shade --light 'point pos=1e20,0,1e20 I=1e38' --brdf 'lambert diff=0.8'
# a direction whose squared length underflows binary32 is still normalized: l = (0.707, 0, 0.707)
expect_close "tiny direction"    1e-6 '0.180063263 0.180063263 0.180063263' -- shade --light 'directional dir=1e-30,0,1e-30' --brdf 'lambert diff=0.8'
