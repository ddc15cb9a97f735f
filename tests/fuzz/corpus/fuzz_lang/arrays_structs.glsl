struct L { vec3 d; float w[2]; };
struct S { L ls[2]; int n; };
float sum(float a[3]) { return a[0] + a[1] + a[2]; }
float[2] pair(float x) { return float[2](x, -x); }
S s = S(L[2](L(vec3(1.0), float[2](0.5, 1.5)), L(vec3(2.0), float[](2.5, 3.5))), 2);
int i = 1;
s.ls[i].w[0] = 4.0;
s.ls[i].d.y += 1.0;
s;
sum(float[3](1.0, 2.0, 3.0)) + pair(x)[1];
const int N = 2;
int a[N * 2];
for (int k = 0; k < a.length(); k++) a[k] = k * k;
a == int[4](0, 1, 4, 9);
a[i + 2];
