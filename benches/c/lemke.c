/*
 * A plain dense-tableau Lemke in C: the reference the Rust Lemke is measured
 * against (benches/lemke_c.rs). Textbook algorithm, as Siconos' lexicolemke:
 * covering vector e, tableau B^-1 [I, -M, -e | q] (n rows, 2n + 2 columns,
 * row-major, contiguous), lexicographic minimum-ratio test on ties, pivot
 * entries above 1e-12 times the column's largest magnitude. No allocation:
 * the caller passes a workspace of lemke_c_work_size(n) doubles.
 *
 * Returns the number of pivots (> 0 or 0 when q >= 0) on a solution, -1 on
 * a secondary ray, -2 at the pivot cap. z and w (length n) get the basic
 * solution read from the final tableau (no re-solve, no check).
 */
#include <math.h>
#include <stddef.h>

size_t lemke_c_work_size(int n) { return (size_t)n * (2 * n + 2); }

int lemke_c(int n, const double *m, const double *q, double *z, double *w,
            double *work, int max_pivots) {
    const int cols = 2 * n + 2, rhs = 2 * n + 1, z0 = 2 * n;
    double *t = work;
    int basic[64], cand[64]; /* n <= 64 */
    int all_nonneg = 1;
    for (int i = 0; i < n; i++) all_nonneg &= q[i] >= 0.0;
    if (all_nonneg) {
        for (int i = 0; i < n; i++) { z[i] = 0.0; w[i] = q[i]; }
        return 0;
    }
    for (int i = 0; i < n; i++) {
        double *row = t + (size_t)i * cols;
        for (int j = 0; j < cols; j++) row[j] = 0.0;
        row[i] = 1.0;
        for (int j = 0; j < n; j++) row[n + j] = -m[i * n + j];
        row[z0] = -1.0;
        row[rhs] = q[i];
        basic[i] = i;
    }
    /* First pivot: the most negative q_i (largest index among ties). */
    int r = 0;
    for (int i = 1; i < n; i++) if (q[i] <= q[r]) r = i;
    int c = z0, pivots = 0;
    for (;;) {
        /* Gauss-Jordan pivot on (r, c). */
        double *prow = t + (size_t)r * cols;
        double inv = 1.0 / prow[c];
        for (int j = 0; j < cols; j++) prow[j] *= inv;
        prow[c] = 1.0;
        for (int i = 0; i < n; i++) {
            if (i == r) continue;
            double *row = t + (size_t)i * cols;
            double f = row[c];
            if (f != 0.0) {
                for (int j = 0; j < cols; j++) row[j] -= f * prow[j];
                row[c] = 0.0;
            }
        }
        pivots++;
        int leaving = basic[r];
        basic[r] = c;
        if (leaving == z0) break;
        if (pivots >= max_pivots) return -2;
        c = leaving < n ? leaving + n : leaving - n;
        /* Candidates: entries above 1e-12 times the column's largest. */
        double colmax = 0.0;
        for (int i = 0; i < n; i++) colmax = fmax(colmax, fabs(t[(size_t)i * cols + c]));
        int k = 0;
        for (int i = 0; i < n; i++)
            if (t[(size_t)i * cols + c] > 1e-12 * colmax) cand[k++] = i;
        if (k == 0) return -1;
        /* Lexicographic minimum ratio: rhs, then the columns of B^-1. */
        double min = INFINITY;
        for (int a = 0; a < k; a++) {
            int i = cand[a];
            double v = fmax(t[(size_t)i * cols + rhs], 0.0) / t[(size_t)i * cols + c];
            if (v < min) min = v;
        }
        int kept = 0, z0_row = -1;
        for (int a = 0; a < k; a++) {
            int i = cand[a];
            double v = fmax(t[(size_t)i * cols + rhs], 0.0) / t[(size_t)i * cols + c];
            if (v <= min) { cand[kept++] = i; if (basic[i] == z0) z0_row = i; }
        }
        k = kept;
        if (z0_row >= 0) { r = z0_row; continue; }
        for (int col = 0; col < n && k > 1; col++) {
            min = INFINITY;
            for (int a = 0; a < k; a++) {
                int i = cand[a];
                double v = t[(size_t)i * cols + col] / t[(size_t)i * cols + c];
                if (v < min) min = v;
            }
            kept = 0;
            for (int a = 0; a < k; a++) {
                int i = cand[a];
                if (t[(size_t)i * cols + col] / t[(size_t)i * cols + c] <= min) cand[kept++] = i;
            }
            k = kept;
        }
        r = cand[0];
    }
    for (int i = 0; i < n; i++) { z[i] = 0.0; w[i] = 0.0; }
    for (int i = 0; i < n; i++) {
        int v = basic[i];
        double x = fmax(t[(size_t)i * cols + rhs], 0.0);
        if (v < n) w[v] = x;
        else if (v < 2 * n) z[v - n] = x;
    }
    return pivots;
}
