int s = 0;
for (int i = 0; i < 10; i++) { if (i % 3 == 0) continue; s += i; }
int j = 0; while (j < 5) { j++; if (j == 4) break; }
do { j--; } while (j > 0);
s; j;
