/* Rows of the batch table for sin, cos, acos, atan2 (included inside the array of
 * src/batch/table.c: ROWS(...) and ROWS_P(...) lines only). */
ROWS(sin, u1, 1, 1, 1, 0, 0, "all x (|x| >= 2^19 pi/2, Inf, NaN by the scalar built-in)", -1e4, 1e4,
     0, 0, NULL, 78)
ROWS(sin, bits22, 1, 1, 0, B22, 0x1p-30,
     "|x| <= 1000 (beyond: the scalar built-in); error <= 2^-22 |sin x| + 2^-30", -1000, 1000, 0, 0,
     NULL, 15)
ROWS(sin, bits12, 1, 1, 0, B12, 0x1p-30,
     "|x| <= 1000 (beyond: the scalar built-in); error <= 2^-12 |sin x| + 2^-30", -1000, 1000, 0, 0,
     NULL, 13)
ROWS(cos, u1, 1, 1, 1, 0, 0, "all x (|x| >= 2^19 pi/2, Inf, NaN by the scalar built-in)", -1e4, 1e4,
     0, 0, NULL, 78)
ROWS(cos, bits22, 1, 1, 0, B22, 0x1p-30,
     "|x| <= 1000 (beyond: the scalar built-in); error <= 2^-22 |cos x| + 2^-30", -1000, 1000, 0, 0,
     NULL, 16)
ROWS(cos, bits12, 1, 1, 0, B12, 0x1p-30,
     "|x| <= 1000 (beyond: the scalar built-in); error <= 2^-12 |cos x| + 2^-30", -1000, 1000, 0, 0,
     NULL, 14)
ROWS(acos, u1, 1, 1, 1, 0, 0, "-1 <= x <= 1 (NaN outside)", -1, 1, 0, 0, NULL, 78)
ROWS(acos, bits22, 1, 1, 0, B22, 0, "-1 <= x <= 1 (NaN outside)", -1, 1, 0, 0, NULL, 16)
ROWS(acos, bits12, 1, 1, 0, B12, 0, "-1 <= x <= 1 (NaN outside)", -1, 1, 0, 0, NULL, 11)
ROWS(atan2, u1, 2, 1, 1, 0, 0,
     "all y, x (inputs y x; (0, 0), (Inf, Inf), NaN by the scalar built-in)", -1e4, 1e4, -1e4, 1e4,
     NULL, 96)
ROWS(atan2, bits22, 2, 1, 0, B22, 0x1p-126,
     "all y, x (inputs y x; beyond 2^126, (0, 0), NaN by the scalar built-in); results below "
     "2^-126 may flush to 0",
     -1e4, 1e4, -1e4, 1e4, NULL, 33)
