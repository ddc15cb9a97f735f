# BRDF Explorer .brdf files: --brdf 'file=PATH NAME=VALUE ...' in shade, sweep, check, render;
# brdf --export; malformed files (exit 2 naming FILE:LINE); run-time errors (exit 1).
. tests/e2e/lib.sh

D=tests/brdf
LIGHT='directional dir=0,0,1 I=1' # E = 1 at normal incidence: L_o = f

# tests/brdf/constructs.brdf is kd/pi * tint at its defaults (kd 0.5, tint 1,0.5,0.25)
pi=3.14159265358979323846
ref=$(awk -v pi=$pi 'BEGIN { printf "%.17g %.17g %.17g", 0.5/pi, 0.25/pi, 0.125/pi }')
expect_close "every construct" 1e-15 "$ref" -- shade -p double --light "$LIGHT" --brdf "file=$D/constructs.brdf"
ref=$(awk -v pi=$pi 'BEGIN { printf "%.17g %.17g %.17g", 0.4/pi, 0.1/pi, 0.2/pi }')
expect_close "parameters set" 1e-15 "$ref" -- shade -p double --light "$LIGHT" --brdf "file=$D/constructs.brdf kd=0.1 doubled=1 tint=2,0.5,1"
ref=$(awk -v pi=$pi 'BEGIN { printf "%.17g %.17g %.17g", 0.4/pi, 0.4/pi, 0.4/pi }')
expect_close "grey tint"      1e-15 "$ref" -- shade -p double --light "$LIGHT" --brdf "file=$D/constructs.brdf kd=0.4 tint=1"
expect "crlf lines"  0 '0.5 0.5 0.5' '' -- shade --light "$LIGHT" --brdf "file=$D/crlf.brdf"
expect "below the horizon" 0 '0 0 0' '' -- shade --light "$LIGHT" --v 0,0,-1 --brdf "file=$D/crlf.brdf"
expect "ieee division by zero" 0 'inf nan -inf' '~L_o overflows' -- shade --light "$LIGHT" --brdf "file=$D/ieee.brdf"
expect "explain" 0 '~brdf file tests/brdf/constructs.brdf (3 parameters)
  kd = 0.5  (float 0..1, line 10)
  doubled = false  (bool, line 11)
  tint = (1, 0.5, 0.25)  (color, line 12)' '' -- shade --explain --light "$LIGHT" --brdf "file=$D/constructs.brdf"
expect "explain f" 0 '~  f = (0.15915494, 0.07957747, 0.039788734)' '' -- shade --explain --light "$LIGHT" --brdf "file=$D/constructs.brdf"
expect "explain json" 0 '~"brdf_file": "tests/brdf/constructs.brdf", "parameters": [{"name": "kd", "type": "float", "value": 0.5, "min": 0, "max": 1, "line": 10}, {"name": "doubled", "type": "bool", "value": false, "line": 11}' '' -- shade -f json --explain --light "$LIGHT" --brdf "file=$D/constructs.brdf"

# parameters on the command line
expect "unknown name" 2 '' "error: tests/brdf/constructs.brdf: no parameter 'kdd' (did you mean 'kd'?)" -- shade --light "$LIGHT" --brdf "file=$D/constructs.brdf kdd=1"
expect "outside the range" 2 '' "error: tests/brdf/constructs.brdf: kd=1.5: outside the file's range 0..1 (line 10)" -- shade --light "$LIGHT" --brdf "file=$D/constructs.brdf kd=1.5"
expect "nan value" 2 '' "error: tests/brdf/constructs.brdf: kd=nan: expected a finite number" -- shade --light "$LIGHT" --brdf "file=$D/constructs.brdf kd=nan"
expect "bool value" 2 '' "error: tests/brdf/constructs.brdf: doubled=2: expected 0, 1, true or false" -- shade --light "$LIGHT" --brdf "file=$D/constructs.brdf doubled=2"
expect "given twice" 2 '' "error: tests/brdf/constructs.brdf: kd= is given twice" -- shade --light "$LIGHT" --brdf "file=$D/constructs.brdf kd=0.1 kd=0.2"
expect "endless file" 2 '' "error: /dev/zero: over 1 MiB: not a .brdf file" -- shade --light "$LIGHT" --brdf "file=/dev/zero"
expect "a directory" 2 '' "error: $D: Is a directory" -- shade --light "$LIGHT" --brdf "file=$D"
expect "no file" 2 '' "error: $D/none.brdf: No such file or directory" -- shade --light "$LIGHT" --brdf "file=$D/none.brdf"

# malformed files: exit 2, FILE:LINE and what is wrong
while read -r name where what; do
    expect "malformed $name" 2 '' "~error: $D/bad/$name.brdf:$where: $what" -- shade --light "$LIGHT" --brdf "file=$D/bad/$name.brdf"
done <<'TABLE'
header 1 the first line must be 'analytic'
float_count 3 expected 'float NAME MIN MAX DEFAULT'
float_nan 3 float a: 'nan' is not a finite number
float_order 3 float a: MIN 1 is above MAX 0
float_default 3 float a: the default 2 is outside MIN..MAX 0..1
bool_value 3 bool b: '2' is not 0 or 1
color_count 3 expected 'color NAME R G B'
type 3 unknown parameter type 'int'
name 3 float: expected a GLSL name
duplicate 4 parameter 'a' is already declared on line 3
reserved 3 'max' is a reserved or built-in name
nested 3 ::begin shader inside the 'parameters' section opened on line 2
mismatch 3 ::end shader does not close the 'parameters' section
stray_end 2 ::end shader outside any section
section 2 unknown section 'lights'
unclosed 2 the 'shader' section opened here has no ::end shader
no_shader 3 no '::begin shader' section
outside 2 text outside a section
two_shaders 5 a second 'shader' section
no_brdf 2 the shader must define vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) (unknown function 'BRDF')
brdf_type 2 the shader must define vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) (its BRDF returns another type)
glsl 5:22 expected an expression
array 3:63 arrays of arrays are not GLSL ES 3.00
recursion 4:37 'f' calls itself
TABLE

# a loop past its bound: exit 1 naming the loop, no output, no image
expect "loop bound shade" 1 '' "error: shade: $D/loop.brdf:7:5: more than 100000 loop iterations in one evaluation" -- shade --light "$LIGHT" --brdf "file=$D/loop.brdf"
expect "loop bound check" 1 '' "error: check: $D/loop.brdf:7:5: more than 100000 loop iterations in one evaluation" -- check --brdf "file=$D/loop.brdf" --theta 0
expect "loop bound sweep" 1 '*' "error: sweep: row 1: $D/loop.brdf:7:5: more than 100000 loop iterations in one evaluation" -- sweep --brdf "file=$D/loop.brdf" --var theta_o=0:80:3
expect "loop bound render" 1 '' "error: render: $D/loop.brdf:7:5: more than 100000 loop iterations in one evaluation" -- render --brdf "file=$D/loop.brdf" --size 16x16 -o "$e2e_tmp/loop.exr"
expect "loop bound at row 8" 1 '*' "error: sweep: row 8: $D/loop_grazing.brdf:8:5: more than 100000 loop iterations in one evaluation" -- sweep --threads 1 --brdf "file=$D/loop_grazing.brdf" --var theta_o=0:80:9
verdict "no image of a failed shader" test ! -e "$e2e_tmp/loop.exr"

# sweep: $var in the parameters; the file is compiled once
ref=$(awk -v pi=$pi 'BEGIN { printf "0,0.1,%.17g,%.17g,%.17g\n0,0.3,%.17g,%.17g,%.17g", 0.1/pi, 0.05/pi, 0.025/pi, 0.3/pi, 0.15/pi, 0.075/pi }')
out=$("$SHADECALC" sweep -p double --brdf "file=$D/constructs.brdf kd=\$k" --var theta_o=0 --var k=0.1,0.3 | tail -n 2)
verdict "sweep \$var" sh -c 'printf "%s\n%s\n" "$1" "$2" | tr "," " " | awk "NR <= 2 { for (i = 1; i <= NF; i++) w[NR, i] = \$i } NR > 2 { for (i = 1; i <= NF; i++) { d = \$i - w[NR - 2, i]; if (d < 0) d = -d; if (d > 1e-15 * (w[NR - 2, i] < 0 ? -w[NR - 2, i] : w[NR - 2, i])) exit 1 } }"' _ "$ref" "$out"
expect "sweep range" 2 '*' "~kd=2: outside the file's range 0..1" -- sweep --brdf "file=$D/constructs.brdf kd=\$k" --var theta_o=0 --var k=0.5,2
expect "tier refused" 2 '' "error: sweep: --tier accurate: the batch kernels do not cover this scene: a BRDF file's GLSL runs in the interpreter, not in the batch kernels" -- sweep --light "$LIGHT" --brdf "file=$D/crlf.brdf" --var theta_o=0:80:3 --tier accurate

# check: Lambertian kd/pi * tint has albedo kd * tint at every angle
expect "check albedo" 0 '~       0  0.500000   0.250000   0.125000' '' -- check --brdf "file=$D/constructs.brdf" --theta 0,60
expect "check reciprocal" 0 '~reciprocity error 0: reciprocal' '' -- check --brdf "file=$D/constructs.brdf" --theta 0,60

# render: the refused plan falls back to the scalar shading of every pixel
expect "render" 0 '' '' -- render --brdf "file=$D/constructs.brdf" --size 16x16 -o "$e2e_tmp/c.exr"
verdict "render wrote an image" test -s "$e2e_tmp/c.exr"

# brdf --export: the built-in model's math as a file (test_brdf_file.c compares them all)
expect "export" 0 '' '' -- brdf --export 'cook-torrance alpha=0.3 D=beckmann G=smith F=exact' -o "$e2e_tmp/ct.brdf"
a=$("$SHADECALC" shade -p double --light 'directional dir=0.3,0.2,1' --v 0.5,0,1 --brdf 'cook-torrance alpha=0.3 D=beckmann G=smith F=exact')
b=$("$SHADECALC" shade -p double --light 'directional dir=0.3,0.2,1' --v 0.5,0,1 --brdf "file=$e2e_tmp/ct.brdf")
verdict "export agrees" test "$a" = "$b"
expect "export a file" 2 '' "~error: brdf: --export 'file=$D/crlf.brdf': not a built-in BRDF" -- brdf --export "file=$D/crlf.brdf"
expect "export legacy" 2 '' "~not a built-in BRDF" -- brdf --export opengl
expect "export nothing" 2 '' "error: brdf: no --export SPEC given (see 'shadecalc brdf --help')" -- brdf
expect "export bad spec" 2 '' "~error: brdf: brdf ward: unknown key 'm'" -- brdf --export 'ward m=3'
expect "export help" 0 '~usage: shadecalc brdf --export SPEC' '' -- brdf --help

# area lights: the reference and point methods take a file BRDF; representative-point, which
# lights the diffuse and specular parts apart, refuses it
expect "area check" 0 '~reference  ' '' -- check --light 'sphere center=0,0,2 radius=1' --brdf "file=$D/constructs.brdf"
verdict "area check without representative-point" sh -c '! "$SHADECALC" check --light "sphere center=0,0,2 radius=1" --brdf "file=$1/constructs.brdf" | grep -q representative' _ "$D"
expect "representative-point refused" 2 '' "error: light 1: method=representative-point: not for a BRDF file (it lights the diffuse and specular parts apart; a file gives f alone)" -- shade --light 'sphere center=0,0,2 radius=1 method=representative-point' --brdf "file=$D/constructs.brdf"
