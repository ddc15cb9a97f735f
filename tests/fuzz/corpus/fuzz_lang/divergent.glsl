float f(float a, out float b) { b = a; if (a < 0.0) return -a; for (int i = 0; i < int(a * 3.0); i++) b += v.y; return b; }
float b; float r = x > 0.0 ? f(x, b) : f(v.z, b);
int k = int(v.x); ivec2(k / (k - 1), k << 3);
vec3 w = v; w[int(abs(x))] = 1.0;
vec2(r, b)
