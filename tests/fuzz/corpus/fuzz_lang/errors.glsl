float f(float t) { return f(t); }
1 + 2.0; vec3 q; q.xx = vec2(1.0); const int c = 1; c = 2; x ? 1 : 2;
