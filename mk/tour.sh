#!/bin/sh
# The main job (`make run`): a tour of what shadecalc computes. Each step prints the command,
# then its output.
set -eu
bin=${1:-build/shadecalc}
step() {
    printf '\n$ shadecalc'
    for a in "$@"; do
        case $a in *' '*|*'('*|*'*'*) printf " '%s'" "$a" ;; *) printf ' %s' "$a" ;; esac
    done
    printf '\n'
    "$bin" "$@"
}
echo "shadecalc tour: GLSL ES built-ins and the lighting equations from the shell"
echo "(every command has --help; the manual is 'man ./man/shadecalc.1')"

echo; echo "== GLSL ES built-ins in each precision =="
step eval 'normalize(vec3(3,0,4))'
step eval 'reflect(vec3(1,-1,0), vec3(0,1,0))'
step eval --precision highp 'inversesqrt(1e-40)'
step eval --precision mediump 'inversesqrt(1e-40)'
step eval --precision mediump --ulp 'exp2(10.3)'
step eval --hex 'pow(2.0, 0.5)'
step eval --format json 'mat2(1,2,3,4) * vec2(1,1)'

echo; echo "== One shading value, every intermediate (docs/formulas.md §6) =="
step shade --explain --light 'spot pos=0,4,0 dir=0,-1,0 I=50 spot=directx inner=20 outer=30 exp=1' \
    --light 'point pos=3,3,0 I=20 atten=pixar fmax=2 fc=1 rc=1 se=2' \
    --brdf 'cook-torrance diff=0.5,0.1,0.1 amb=0.5,0.1,0.1 f0=0.04 alpha=0.3 D=ggx G=smith F=schlick' \
    --n 0,1,0 --v 0,1,1 --ambient 0.05

echo; echo "== The OpenGL 1.x fixed-function equation, reproduced =="
step shade --precision double --light 'spot pos=1,3,0 dir=0,-1,-1 atten=clq sc=1 sl=0.05 sq=0.02 cutoff=30 exp=10 amb=0.1' \
    --brdf 'opengl emission=0.1,0,0 amb=0.2 diff=0.8,0.5,0.2 spec=0.5 m=20' --ambient 0.2 \
    --p 1,0,-4 --eye 0,0,0

echo; echo "== Are the models physical? Albedo and reciprocity =="
step check --theta 0,30,60,85,89.9 --brdf 'blinn-phong diff=0 spec=1 m=8.8' \
    --brdf 'ward form=duer diff=0 spec=1 alpha=0.2' --brdf 'ward form=gmd diff=0 spec=1 alpha=0.2' \
    --brdf 'phong form=original diff=0 spec=1 m=10'

echo; echo "== Gouraud or Phong, how many triangles? Error against the exact sphere (docs/formulas.md §8) =="
compare_dir=$(dirname "$bin")/compare
mkdir -p "$compare_dir"
step render --compare --size 256x256 --output-dir "$compare_dir"
echo "(images and error maps: $compare_dir/*.exr)"

echo; echo "== Sweeps: the lecture's figures as tables, SVG plots and an EXR image =="
out=${SHADECALC_OUT:-out}
mkdir -p "$out"
step sweep --var x=0:1:6 'pow(x, 32.0)'
step sweep --var r=0:12:7 --light 'point pos=0,0,$r I=1 atten=window rstart=1 rend=10' --format tsv
for preset in attenuation spot lobe albedo; do
    step sweep --preset "$preset" --plot "$out/$preset.svg" -o "$out/$preset.csv"
done
step sweep --var theta_h=0:90:91 --var theta_d=0:90:91 --brdf 'cook-torrance alpha=0.2' \
    --image "$out/slice.exr"
echo "(plots, tables and the theta_h x theta_d image slice, written to $out/:"
ls "$out"
echo ")"

echo; echo "== Speed against accuracy: the shading kernel's tiers on this CPU (make bench: all kernels) =="
step bench --n 4096 --repeat 3 --tier accurate,bits12 shade
