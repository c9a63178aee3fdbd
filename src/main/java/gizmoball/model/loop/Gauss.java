package gizmoball.model.loop;

/**
 * Gaussian elimination with partial pivoting on a small dense system, for the contact solve ({@link NormalImpulses}).
 * A column whose pivot is negligible (a row that depends on others: a face and the corner flush with it, both
 * touched along one normal) gets 0, and its equation is left to the others.
 */
final class Gauss {
    /** Relative size below which a pivot counts as zero. */
    private static final double DEPENDENT = 1e-12;

    private Gauss() {
    }

    /** Solves the system whose augmented matrix is {@code m} (n rows of n + 1), in place; returns the unknowns. */
    static double[] solve(double[][] m) {
        int n = m.length;
        double largest = 0;
        for (double[] row : m) {
            for (int c = 0; c < n; c++) {
                largest = Math.max(largest, Math.abs(row[c]));
            }
        }
        double negligible = DEPENDENT * Math.max(largest, Double.MIN_NORMAL);
        int[] pivotRow = new int[n];
        boolean[] used = new boolean[n];
        boolean[] free = new boolean[n];
        for (int c = 0; c < n; c++) {
            int best = -1;
            for (int r = 0; r < n; r++) {
                if (!used[r] && (best < 0 || Math.abs(m[r][c]) > Math.abs(m[best][c]))) {
                    best = r;
                }
            }
            if (best < 0 || Math.abs(m[best][c]) <= negligible) {
                free[c] = true;
                continue;
            }
            used[best] = true;
            pivotRow[c] = best;
            for (int r = 0; r < n; r++) {
                if (r != best && m[r][c] != 0) {
                    double factor = m[r][c] / m[best][c];
                    for (int k = c; k <= n; k++) {
                        m[r][k] -= factor * m[best][k];
                    }
                }
            }
        }
        double[] x = new double[n];
        for (int c = 0; c < n; c++) {
            if (!free[c]) {
                x[c] = m[pivotRow[c]][n] / m[pivotRow[c]][c];
            }
        }
        return x;
    }
}
