# Decimal literals are rounded once, correctly, to the precision: not to binary64 first, whose
# ties to even at a midpoint of the narrower format can land on the wrong neighbour. Double
# precision reads the same binary64 as before (the midpoint itself, bits 0x3ab5c87fb0000000).
#   7.038531e-26: binary64 reads it as the binary32 midpoint 0x1.5c87fbp-84; the decimal lies
#     below it, so highp is 0x1.5c87fap-84 (strtof, correctly rounded: bits 0x15ae43fd), whose
#     shortest decimal is the literal itself; ties to even gave 0x1.5c87fcp-84 (7.0385313e-26).
#   1.000488281250000000000000000001: binary64 reads it as 1 + 2^-11, the binary16 midpoint of
#     1 and 1 + 2^-10; the decimal lies above it, so mediump is 1 + 2^-10 (bits 0x3c01, printed
#     1.001), where ties to even gave 1. Its negation: -1.001 (bits 0xbc01).
. tests/e2e/lib.sh

above=1.000488281250000000000000000001

expect "highp literal"            0 '7.038531e-26' '' -- eval --precision highp 7.038531e-26
expect "highp literal bits"       0 '0x15ae43fd' '' -- eval --precision highp --hex 7.038531e-26
expect "highp negative literal"   0 '-7.038531e-26' '' -- eval -- -7.038531e-26
expect "double keeps binary64"    0 '0x3ab5c87fb0000000' '' -- eval --precision double --hex 7.038531e-26
expect "mediump literal"          0 '1.001' '' -- eval --precision mediump "$above"
expect "mediump vector operand"   0 'vec2(1.001, -1.001)' '' -- eval -p mediump "vec2($above, -$above)"
expect "mediump vector bits"      0 'vec2(0x3c01, 0xbc01)' '' -- eval -p mediump --hex "vec2($above, -$above)"
expect "define"                   0 '7.038531e-26' '' -- eval -D k=7.038531e-26 'k'

printf 'float tiny() { return 7.038531e-26; }\ntiny();\n' >"$e2e_tmp/tiny.glsl"
expect "glsl file literal"        0 '7.038531e-26' '' -- eval --file "$e2e_tmp/tiny.glsl"

printf 'analytic\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(7.038531e-26, 1.0, %s); }\n::end shader\n' \
    "$above" >"$e2e_tmp/tiny.brdf"
# E = 1 at normal incidence: L_o = f (1 + 2^-11 is a binary32: 1.0004883 in highp)
light='directional dir=0,0,1 I=1'
expect "brdf file literal highp"  0 '7.038531e-26 1 1.0004883' '' -- shade -p highp --light "$light" --brdf "file=$e2e_tmp/tiny.brdf"
expect "brdf file literal mediump" 0 '0 1 1.001' '' -- shade -p mediump --light "$light" --brdf "file=$e2e_tmp/tiny.brdf"
expect "sweep expression literal" 0 'x,value
1,7.038531e-26' '' -- sweep --precision highp --var x=1 'x * 7.038531e-26'
