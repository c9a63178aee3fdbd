package gizmoball.model.loop;

import java.util.Arrays;

/**
 * The Cholesky factor L L^T of J_A J_A^T, the coupling of the rows in the active set of {@link NormalImpulses}, kept
 * as rows join so that solving the set's equalities costs O(m^2) per change, not the O(m^3) of an elimination from
 * scratch: a cluster of 30 touching balls joins some 40 rows per projection, and it projects once per round of
 * impacts. A joining row costs one forward substitution. When rows leave, the factor of the rows that stay is built
 * again in the order they joined: leaving is much rarer than joining.
 *
 * <p>J_A J_A^T is positive semidefinite; it is definite while no row of the set depends on the others. A joining row
 * whose pivot (its squared distance from the span of the set's rows, on the coupling's scale) is negligible
 * depends on them, and is refused.
 */
final class ActiveRowsFactor {
    /** How an impulse on one row changes what another closes by: J_i . J_j. */
    @FunctionalInterface
    interface Coupling {
        double of(int i, int j);
    }


    private final Coupling coupling;
    /** The set's rows in the order they joined: factor row k is {@code order[k]}. */
    private final int[] order;
    /** The lower-triangular factor, row k holding its k + 1 entries. */
    private final double[][] lower;
    /** A forward substitution's values, reused. */
    private final double[] work;
    private int size;
    /** The largest diagonal coupling of the set: the scale a pivot is negligible on. */
    private double scale;

    ActiveRowsFactor(int rows, Coupling coupling) {
        this.coupling = coupling;
        this.order = new int[rows];
        this.lower = new double[rows][];
        this.work = new double[rows];
    }

    /** Adds {@code row} to the set; false, leaving the set as it was, if the row depends on the rows already in it. */
    boolean add(int row) {
        double[] entries = new double[size + 1];
        double pivot = coupling.of(row, row);
        for (int k = 0; k < size; k++) {
            double[] lk = lower[k];
            double sum = coupling.of(row, order[k]);
            for (int p = 0; p < k; p++) {
                sum -= entries[p] * lk[p];
            }
            entries[k] = sum / lk[k];
            pivot -= entries[k] * entries[k];
        }
        double newScale = Math.max(scale, coupling.of(row, row));
        if (pivot <= Tolerances.DEPENDENT_PIVOT * newScale) {
            return false;
        }
        entries[size] = Math.sqrt(pivot);
        lower[size] = entries;
        order[size] = row;
        size++;
        scale = newScale;
        return true;
    }

    /**
     * Keeps only the rows for which {@code keep} is true, in the order they joined; false if one of them no longer
     * counts as independent of those before it (rounding on a set at the edge of dependence).
     */
    boolean keepOnly(boolean[] keep) {
        int[] staying = new int[size];
        int count = 0;
        for (int k = 0; k < size; k++) {
            if (keep[order[k]]) {
                staying[count++] = order[k];
            }
        }
        size = 0;
        scale = 0;
        for (int k = 0; k < count; k++) {
            if (!add(staying[k])) {
                return false;
            }
        }
        return true;
    }

    /**
     * The impulses of the set's rows that make each close by exactly {@code base} (per row, what it closes by before
     * any impulse), in {@code out}; every other row gets 0.
     */
    void solve(double[] base, double[] out) {
        Arrays.fill(out, 0);
        for (int k = 0; k < size; k++) {
            double[] lk = lower[k];
            double sum = base[order[k]];
            for (int p = 0; p < k; p++) {
                sum -= lk[p] * work[p];
            }
            work[k] = sum / lk[k];
        }
        // L^T x = work, by rows of L: each unknown, once found, is taken out of the equations above it.
        for (int k = size - 1; k >= 0; k--) {
            double[] lk = lower[k];
            double x = work[k] / lk[k];
            out[order[k]] = x;
            for (int p = 0; p < k; p++) {
                work[p] -= lk[p] * x;
            }
        }
    }
}
