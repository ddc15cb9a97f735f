int g(int x);
int f(int x) { switch (x) { case 0: return 10; case 1: case 2: x += g(x); break; default: x = -1; } return x; }
int g(int x) { return x * 2; }
uint u = 3u;
switch (u) { case 1u + 2u: f(1); break; default: f(9); }
float i; modf(2.75, i); i;
vec3 j; modf(v, j); j;
f(0); f(2); f(7);
