mat2x3 m = mat2x3(1, 2, 3, 4, 5, 6);
mat3x2 n = mat3x2(m[0], m[1]);
m * vec2(1.0, x); vec3(1.0) * m; n * m; m[1][2] = 9.0; m; int k = 1; m[k]; m[k].yx;
mat4(mat2(2.0)); mat2x4(v, x, v, 1.0) == mat2x4(1.0); transpose(mat2(1, 2, 3, 4));
