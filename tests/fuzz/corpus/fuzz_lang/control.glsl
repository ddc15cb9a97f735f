#version 300 es
precision highp float;
const float PI = 3.14159265;
/* block comment */ bool b = x > 0.25 && v.y < 0.0 || !(x == 1.0) ^^ true;
float r = b ? sin(PI * x) : cos(PI * x);
{ float r = 2.0; r *= 3.0; r /= 4.0; r -= 1.0; r += 0.5; }
r; ++r; r--; r; -r; +r;
