#!/bin/sh
# The main job (`make run`): a short tour of what shadecalc computes.
# Each step prints the command, then its output.
set -eu
bin=${1:-build/shadecalc}
step() {
    printf '\n$ shadecalc %s\n' "$*"
    "$bin" "$@"
}
echo "shadecalc tour — GLSL ES built-ins from the shell (see 'man ./man/shadecalc.1')"
step eval 'normalize(vec3(3,0,4))'
step eval 'reflect(vec3(1,-1,0), vec3(0,1,0))'
step eval --precision highp 'inversesqrt(1e-40)'
step eval --precision mediump 'inversesqrt(1e-40)'
step eval --precision mediump --ulp 'exp2(10.3)'
step eval --hex 'pow(2.0, 0.5)'
step eval --format json 'mat2(1,2,3,4) * vec2(1,1)'
