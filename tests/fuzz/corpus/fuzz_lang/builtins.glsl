lessThan(vec2(1, 2), vec2(2, 1)); any(bvec3(false, true, false)); not(bvec2(true));
abs(-3); clamp(ivec3(-5, 5, 50), 0, 10); isnan(x / 0.0); floatBitsToUint(x);
packHalf2x16(vec2(x, -x)); unpackSnorm2x16(0x7fff8001u); max(uvec2(3u), 4u);
