# Messages and exit statuses (issue 11 §8): specs that contradict themselves, did-you-mean for
# kinds and keys, scene files and OBJ files, user input escaped in messages.
. tests/e2e/lib.sh
t=$e2e_tmp
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
