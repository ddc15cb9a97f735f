/* Rows of the batch table for sin, cos, acos, atan2 (included inside the array of
 * src/batch/table.c: ROWS(...) and ROWS_P(...) lines only). */
