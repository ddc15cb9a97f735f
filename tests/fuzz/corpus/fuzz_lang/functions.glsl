float sq(float a) { return a * a; }
int sq(int a) { return a * a; }
void split(in float y, out int w, inout float acc) { w = int(y); acc += y - float(w); }
int w; float acc = 0.0; split(x * 3.5, w, acc);
sq(x) + acc; sq(w); v.zyx * sq(2.0);
