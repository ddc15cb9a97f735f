/* Rows of the batch table for the attenuation, spot and BRDF kernels (included inside the array
 * of src/batch/table.c: ROWS(...) and ROWS_P(...) lines only). */
