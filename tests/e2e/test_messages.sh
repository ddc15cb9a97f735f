# Messages and exit statuses (issue 11 §8): specs that contradict themselves, did-you-mean for
# kinds and keys, scene files and OBJ files, user input escaped in messages.
. tests/e2e/lib.sh
t=$e2e_tmp

expect_file() { # NAME PATH: the file exists and is not empty
    if [ -s "$2" ]; then echo "ok   $1"; echo pass >>"$E2E_COUNTS"
    else echo "FAIL $1: no file $2"; echo fail >>"$E2E_COUNTS"; fi
}
sun="directional dir=0,0,1"

# A key given twice, two keys for one parameter, a negative light colour: errors naming the key.
expect "spec: a key given twice"          2 '' 'error: brdf phong: m= is given twice' -- shade -l "$sun" -b 'phong m=32 m=64'
expect "spec: light key given twice"      2 '' 'error: light point: I= is given twice' -- shade -l 'point pos=0,0,1 I=1 I=2'
expect "spec: alpha= then ay="            2 '' 'error: brdf ward: ay= contradicts alpha= (both set the same parameter)' -- shade -l "$sun" -b 'ward alpha=0.2 ay=0.1'
expect "spec: I= and E="                  2 '' 'error: light directional: E= contradicts I= (both set the same parameter)' -- shade -l "$sun I=1 E=2"
expect "spec: inner= and theta="          2 '' '~theta= contradicts inner=' -- shade -l 'spot pos=0,0,1 dir=0,0,-1 spot=directx inner=5 theta=10'
expect "spec: form= given twice"          2 '' 'error: brdf phong: form= is given twice' -- shade -l "$sun" -b 'phong form=modified form=original'
expect "spec: negative intensity"         2 '' 'error: light point: I=-1: must not be negative' -- shade -l 'point pos=0,0,1 I=-1'
expect "spec: negative light colour"      2 '' '~amb=0,-1,0: must not be negative' -- shade -l "$sun amb=0,-1,0"

# A key the chosen function ignores: a warning, and the result is the spec without it
# (Lambert 0.8/pi at normal incidence, E = 1 at r = 1).
expect "spec: inner= under spot=opengl"   0 '0.25464790894703254 0.25464790894703254 0.25464790894703254' 'warning: light spot: inner= has no effect with spot=opengl; light spot: outer= has no effect with spot=opengl' -- shade -p double -l 'spot pos=0,0,1 dir=0,0,-1 spot=opengl inner=30 outer=10'
expect "spec: sc= without atten=clq"      0 '*' 'warning: light point: sc= has no effect with atten=inverse-square' -- shade -l 'point pos=0,0,1 sc=2'
expect "spec: ior= with F=schlick"        0 '*' 'warning: brdf cook-torrance: ior= has no effect with F=schlick' -- shade -l "$sun" -b 'cook-torrance ior=1.3'
expect "spec: viewer= with a local viewer" 0 '*' 'warning: brdf direct3d9: viewer= has no effect with local-viewer=1' -- shade -l "$sun" -b 'direct3d9 viewer=0,0,1'
expect "spec: f0= with F=exact warns in check" 0 '*' '~f0= has no effect with F=exact' -- check -t 0 -b 'cook-torrance F=exact f0=0.5'

# Did you mean: kinds, keys (by name or a synonym's name), built-in functions.
expect "spec: did you mean a kind"        2 '' "~unknown kind 'phonk' (did you mean 'phong'?" -- shade -l "$sun" -b phonk
expect "spec: did you mean a light kind"  2 '' "~unknown kind 'piont' (did you mean 'point'?" -- shade -l 'piont pos=0,0,1'
expect "spec: shininess= means m="        2 '' "error: brdf phong: unknown key 'shininess' (did you mean 'm='?)" -- shade -l "$sun" -b 'phong shininess=8'
expect "spec: a near key"                 2 '' "~unknown key 'alpah' (did you mean 'alpha='?)" -- shade -l "$sun" -b 'ward alpah=0.1'
expect "spec: did you mean an atten= word"  2 '' "error: light point: atten=pixr: expected none|inverse-square|clq|window|pixar|windowed (did you mean 'pixar'?)" -- shade -l 'point pos=0,0,1 atten=pixr'
expect "spec: a key of another kind"      2 '' "error: light point: unknown key 'dir' (a key of other kinds)" -- shade -l 'point pos=0,0,1 dir=0,0,1'
expect "eval: did you mean normalize"     2 '' "~unknown function 'normalise' (did you mean 'normalize'?)" -- eval 'normalise(vec3(1))'

# User input is quoted with control characters and invalid UTF-8 escaped.
esc=$(printf 'poin\033t')
expect "escaped: a spec kind"             2 '' "~unknown kind 'poin\\x1bt'" -- shade -l "$esc pos=0,0,1"
bad=$(printf 'm=\377\001')
expect "escaped: a spec value"            2 '' "~m=\\xff\\x01: expected a number" -- shade -l "$sun" -b "phong $bad"
expect "escaped: valid UTF-8 kept"        2 '' "~unknown key 'θ'" -- shade -l "$sun" -b 'phong θ=1'

# A sweep variable nothing reads draws flat curves: a warning.
expect "sweep: a variable the light ignores" 0 '*' "warning: sweep: nothing reads variable 'theta_s' (no spec has \$theta_s and it is not an angle of l or v): its values all give the same results" -- sweep --var theta_s=0:10:3 -l 'spot pos=0,0,1 dir=0,0,-1'
expect "sweep: a variable EXPR ignores"   0 '*' "warning: sweep: EXPR does not use variable 'y': its values all give the same results" -- sweep --var x=0:1:3 --var y=1,2 'x*2.0'
expect "sweep: a swizzle is not a use"    0 '*' "~does not use variable 'x'" -- sweep --var x=0:1:3 --var y=1,2 'vec2(y).x'
expect "sweep: \${m} is a use"            0 '*' '' -- sweep --var m=8,32 --var theta_o=0:90:3 -b 'phong m=${m}'

# Scene files: '#' starts a comment anywhere; errors name FILE:LINE; '-' is standard input.
printf 'light point pos=0,0,1 # the key light\nbrdf lambert # diff 0.8\n' >"$t/comment.scene"
expect "scene: a comment after an item"   0 '0.25464790894703254 0.25464790894703254 0.25464790894703254' '' -- shade -p double -s "$t/comment.scene"
printf '# geometry\nlight point pos=0,0,1\nn 0,0,0\n' >"$t/zero.scene"
expect "scene: a zero normal names FILE:LINE" 2 '' "error: $t/zero.scene:3: n 0,0,0: must not be the zero vector" -- shade -s "$t/zero.scene"
expect "option: a zero normal"            2 '' 'error: --n 0,0,0: must not be the zero vector' -- shade -l "$sun" --n 0,0,0
printf 'light point pos=0,0,1\nnn 0,0,1\n' >"$t/typo.scene"
expect "scene: did you mean an item"      2 '' "error: $t/typo.scene:2: unknown item 'nn' (did you mean 'n'?)" -- shade -s "$t/typo.scene"
printf 'light point pos=0,0,1\nn 0,0,1\0 junk\n' >"$t/nul.scene"
expect "scene: a NUL byte is an error"    2 '' "error: $t/nul.scene:2: contains a NUL byte" -- shade -s "$t/nul.scene"
expect_stdin "scene: '-' is standard input" 'light point pos=0,0,1
' 0 '0.25464790894703254 0.25464790894703254 0.25464790894703254' '' -- shade -p double -s -
expect_stdin "scene: stdin errors name it" 'light point pos=0,0,1
n 0,0,0
' 2 '' 'error: standard input:2: n 0,0,0: must not be the zero vector' -- shade -s -
expect "scene: a missing file, exit 1"    1 '' "error: $t/none.scene: No such file or directory" -- shade -s "$t/none.scene"

# OBJ files: a missing file says why (exit 1); malformed content is exit 2 as for a scene file.
expect "obj: cannot open says why"        1 '' "error: $t/none.obj: cannot open: No such file or directory" -- render --mesh "$t/none.obj" -o "$t/o.exr"
printf 'v 0 0 0\nv 1 0 0\nf 1 2 3\n' >"$t/bad.obj"
expect "obj: malformed content is exit 2" 2 '' "error: $t/bad.obj:3: bad vertex index in '3'" -- render --mesh "$t/bad.obj" -o "$t/o.exr"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\0 4\n' >"$t/nul.obj"
expect "obj: a NUL byte is an error"      2 '' "~$t/nul.obj:4: a NUL byte in" -- render --mesh "$t/nul.obj" -o "$t/o.exr"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nfo\033o 1 2 3\n' >"$t/esc.obj"
expect "obj: a statement is escaped"      2 '' "error: $t/esc.obj:4: unknown statement 'fo\\x1bo'" -- render --mesh "$t/esc.obj" -o "$t/o.exr"
expect_stdin "obj: '-' is standard input" 'v 0 0 0
v 1 0 0
v 0 1 0
f 1 2 3
' 0 '' '' -- render --mesh - --size 8x8 -o "$t/stdin.exr"
expect_file "obj: the image from stdin"   "$t/stdin.exr"

# Output names that say another format: refused before any work; --output-dir is created.
expect "render -o t.png is refused"       2 '' "error: render: -o $t/t.png: writes exr, not png: name it .exr (and convert it if need be)" -- render -o "$t/t.png"
expect "sweep --plot p.png is refused"    2 '' '~p.png: writes svg, not png' -- sweep --var x=0:1:2 x --plot "$t/p.png"
expect "sweep --image i.png is refused"   2 '' '~i.png: writes exr, not png' -- sweep --var x=0:1:2 --var y=0:1:2 'x+y' --image "$t/i.png"
expect "sweep -o t.svg is refused"        2 '' "error: sweep: -o $t/t.svg: writes a table, not svg" -- sweep --var x=0:1:2 x -o "$t/t.svg"
expect "sweep --plot to '-' is fine"      0 '~<svg' '' -- sweep --var x=0:1:2 x --plot -
expect "render --compare creates --output-dir" 0 '~gouraud' '' -- render --compare --size 16x16 --output-dir "$t/cmp/new"
expect_file "the compare images are there" "$t/cmp/new/render-exact.exr"
expect "escaped: an expression's token"   2 '' "error: column 3: unexpected character: '\\x1b'" -- eval "$(printf '1+\033[2J')"
expect "escaped: a --var"                 2 '' "~--var x\\x01=1: expected" -- sweep --var "$(printf 'x\001=1')" x
expect "escaped: a file name"             1 '' "error: $t/a\\x09b\\x7f: No such file or directory" -- shade -s "$(printf '%s/a\tb\177' "$t")"
expect "escaped: a lone UTF-8 byte"       2 '' "error: column 3: unexpected character: '\\xc3'" -- eval "$(printf '1+\303')"
expect "escaped: bad UTF-8 in a format"   2 '' "error: eval: unknown format 'j\\xc3(' (glsl, csv, jsonl)" -- eval -f "$(printf 'j\303(')" 1
