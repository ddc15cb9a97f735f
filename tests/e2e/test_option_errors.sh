# Option errors of bench, check and sweep --preset that the other tests do not reach: exit
# status 2, nothing on standard output, a message that names the offending input.
. tests/e2e/lib.sh

# bench: empty lists, lists longer than the table, too many kernels, an unknown option
expect "bench empty isa list"   2 '' 'error: bench: --isa: expected a list such as avx2,scalar' -- bench --isa ,
expect "bench isa list too long" 2 '' 'error: bench: --isa: expected a list such as avx2,scalar' -- bench --isa scalar,scalar,scalar,scalar,scalar
expect "bench empty tier list"  2 '' 'error: bench: --tier: expected a list such as u1,bits12' -- bench --tier ,
expect "bench five sizes"       2 '' 'error: bench: --n: expected at most 4 counts, such as 4096,8388608' -- bench --n 1,2,3,4,5
kernels=$(i=0; while [ $i -lt 33 ]; do printf 'pow '; i=$((i + 1)); done)
# shellcheck disable=SC2086 # 33 words
expect "bench 33 kernels"       2 '' 'error: bench: too many kernels' -- bench $kernels
expect "bench unknown option"   2 '' "~error: bench: unknown option '--frob'" -- bench --frob

# check: the --theta separator, the 17th --brdf, the format, stray arguments, unknown options
expect "check theta separator"  2 '' 'error: check: --theta 0;5: expected numbers separated by commas' -- check --brdf lambert --theta '0;5'
brdfs=$(i=0; while [ $i -lt 17 ]; do printf -- '--brdf lambert '; i=$((i + 1)); done)
# shellcheck disable=SC2086 # 17 options
expect "check 17 brdfs"         2 '' 'error: check: too many --brdf (at most 16)' -- check $brdfs
expect "check unknown format"   2 '' "error: check: unknown format 'xml' (table, csv, json)" -- check --brdf lambert -f xml
expect "check stray argument"   2 '' "error: check: unexpected argument 'lambert'" -- check --brdf lambert lambert
expect "check unknown option"   2 '' "~error: check: unknown option '--frob'" -- check --frob

# sweep --preset: what a preset takes
expect "albedo of a lighting model" 2 '' 'error: sweep: opengl: a lighting model has no albedo; give a BRDF' -- sweep --preset albedo --var theta_i=0 --brdf opengl
expect "albedo of a bad spec"   2 '' "~error: sweep: brdf: unknown kind 'lamp'" -- sweep --preset albedo --var theta_i=0 --brdf lamp
expect "preset with a light"    2 '' 'error: sweep: --preset spot takes no --light or --brdf' -- sweep --preset spot --light 'directional dir=0,0,1'
brdfs=$(i=0; while [ $i -lt 9 ]; do printf -- '--brdf lambert '; i=$((i + 1)); done)
# shellcheck disable=SC2086 # 9 options
expect "albedo of 9 brdfs"      2 '' 'error: sweep: --preset albedo takes at most 8 --brdf' -- sweep --preset albedo --var theta_i=0 $brdfs
expect "preset of two variables" 2 '' 'error: sweep: --preset attenuation sweeps r only' -- sweep --preset attenuation --var x=0:1:2
