#!/bin/sh
# shadecalc eval against a real GLSL ES 3.00 implementation, Mesa's llvmpipe (tests/mesa/):
# types, conversions, operators and the exactly specified built-ins. Skipped where mesa_eval
# was not built (no libegl-dev, libgles-dev) or Mesa gives no surfaceless OpenGL ES 3 context.
. tests/e2e/lib.sh

mesa=$(dirname "$SHADECALC")/tests/mesa_eval
export LIBGL_ALWAYS_SOFTWARE=1 # llvmpipe, whatever GPU the machine has
if [ ! -x "$mesa" ]; then
    echo "skip mesa (mesa_eval not built: Debian's libegl-dev and libgles-dev are missing)"
elif ! printf 'float\t1.0\n' | "$mesa" >/dev/null 2>&1; then
    echo "skip mesa (no surfaceless OpenGL ES 3 context: Debian's libegl-mesa0, libgl1-mesa-dri)"
else
    verdict "eval agrees with Mesa llvmpipe" python3 tests/mesa/compare.py "$mesa" "$SHADECALC" \
        tests/mesa/*.cases
fi
