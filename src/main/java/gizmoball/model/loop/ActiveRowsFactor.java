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
    private int[] order;
    /** The lower-triangular factor, packed by rows: row k's k + 1 entries start at k (k + 1) / 2. */
    private double[] lower;
    /** Per factor row k, the largest diagonal coupling of rows 0..k: the scale a pivot is negligible on. */
    private double[] scaleTo;
    /**
     * Per factor row k, where its entries start: those before are exactly +0.0. A row couples only with the rows that
     * share a ball with it, so in a cluster of 30 balls most of a joining row's first entries are zero, and each sum
     * over a row's entries starts at the later of the two rows' starts. The terms passed over are zero products taken
     * from the sum's first value, a coupling, which is +0.0 where it is zero ({@link ContactRows#coupling} sums from
     * +0.0) or not zero: they change no bit of it. The solves pass over them too, which can change only the sign of a
     * zero (5% off the pockets of fuzz seeds 1000117 and 1000596, every collision the same).
     */
    private int[] start;
    /** A forward substitution's values, reused; a back substitution works in it too. */
    private double[] work;
    /**
     * The right-hand side of {@link #solveKeeping}, and its forward substitution for factor rows 0 to
     * {@code forwardDone} - 1: those values depend only on the factor's rows up to theirs, which a joining row leaves
     * as they are.
     */
    private double[] keptBase;
    private double[] forward;
    private int forwardDone;
    private int size;
    /**
     * A solve writes rows 0 to {@code rows} - 1 of its answer (0 outside the set), the rows of the problem
     * ({@link #clear}) and any that joined: the arrays passed may be longer.
     */
    private int rows;

    /**
     * A factor with room for {@code rows} rows; it grows if more join, and is kept across solves ({@link #clear}), so
     * that solving a cluster allocates nothing once it has seen one as large.
     */
    ActiveRowsFactor(int rows, Coupling coupling) {
        this.coupling = coupling;
        this.order = new int[rows];
        this.lower = new double[rows * (rows + 1) / 2];
        this.scaleTo = new double[rows];
        this.start = new int[rows];
        this.work = new double[rows];
        this.forward = new double[rows];
        this.rows = rows;
    }

    /**
     * Empties the set, for rows 0 to {@code rows} - 1: a solve writes those of its answer and no others (the arrays are
     * kept from the largest cluster seen, and filling all of them at every join cost a pocket of 40 rows more than
     * its own solve where a larger cluster had come before).
     */
    void clear(int rows) {
        size = 0;
        forwardDone = 0;
        this.rows = rows;
    }

    /** Adds {@code row} to the set; false, leaving the set as it was, if the row depends on the rows already in it. */
    boolean add(int row) {
        room(size + 1);
        rows = Math.max(rows, row + 1);
        int at = size * (size + 1) / 2;
        double pivot = coupling.of(row, row);
        int first = size;
        for (int k = 0; k < size; k++) {
            int lk = k * (k + 1) / 2;
            double sum = coupling.of(row, order[k]);
            if (first == size) {
                if (sum == 0) {
                    lower[at + k] = 0;   // (+0 - zero products) / L_kk: +0.0, and the pivot unchanged
                    continue;
                }
                first = k;
            }
            for (int p = Math.max(first, start[k]); p < k; p++) {
                sum -= lower[at + p] * lower[lk + p];
            }
            double entry = sum / lower[lk + k];
            lower[at + k] = entry;
            pivot -= entry * entry;
        }
        double newScale = Math.max(size == 0 ? 0 : scaleTo[size - 1], coupling.of(row, row));
        if (pivot <= Tolerances.DEPENDENT_PIVOT * newScale) {
            return false;
        }
        lower[at + size] = Math.sqrt(pivot);
        order[size] = row;
        scaleTo[size] = newScale;
        start[size] = first;
        size++;
        return true;
    }

    private void room(int rows) {
        if (rows > order.length) {
            int capacity = Math.max(rows, 2 * order.length);
            order = Arrays.copyOf(order, capacity);
            lower = Arrays.copyOf(lower, capacity * (capacity + 1) / 2);
            scaleTo = Arrays.copyOf(scaleTo, capacity);
            start = Arrays.copyOf(start, capacity);
            work = Arrays.copyOf(work, capacity);
            forward = Arrays.copyOf(forward, capacity);
        }
    }

    /**
     * Keeps only the rows for which {@code keep} is true, in the order they joined; false if one of them no longer
     * counts as independent of those before it (rounding on a set at the edge of dependence). The factor's rows before
     * the first that leaves stand as they are (each depends only on the rows before it); those after it join again.
     */
    boolean keepOnly(boolean[] keep) {
        int first = 0;
        while (first < size && keep[order[first]]) {
            first++;
        }
        int count = size;
        size = first;
        forwardDone = Math.min(forwardDone, first);
        for (int k = first + 1; k < count; k++) {
            int row = order[k];
            if (keep[row] && !add(row)) {
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
        for (int k = 0; k < size; k++) {
            work[k] = forwardRow(k, base, work);
        }
        backSubstitute(out);
    }

    /**
     * {@link #solve} for a right-hand side that stays the same, array and values, until the next {@link #clear}: the
     * active set asks it once per joining row, and the forward substitution of the rows before is kept, so a join
     * costs the joining row's forward step and the back substitution, not a whole solve. The same doubles as
     * {@link #solve}.
     */
    void solveKeeping(double[] base, double[] out) {
        if (base != keptBase) {
            keptBase = base;
            forwardDone = 0;
        }
        for (int k = forwardDone; k < size; k++) {
            forward[k] = forwardRow(k, base, forward);
        }
        forwardDone = size;
        System.arraycopy(forward, 0, work, 0, size);
        backSubstitute(out);
    }

    /** Factor row k's step of the forward substitution L y = base, from y's values for the rows before it. */
    private double forwardRow(int k, double[] base, double[] y) {
        int lk = k * (k + 1) / 2;
        double sum = base[order[k]];
        for (int p = start[k]; p < k; p++) {
            sum -= lower[lk + p] * y[p];
        }
        return sum / lower[lk + k];
    }

    /** L^T x = work, by rows of L: each unknown, once found, is taken out of the equations above it; x into out. */
    private void backSubstitute(double[] out) {
        Arrays.fill(out, 0, rows, 0);
        for (int k = size - 1; k >= 0; k--) {
            int lk = k * (k + 1) / 2;
            double x = work[k] / lower[lk + k];
            out[order[k]] = x;
            for (int p = start[k]; p < k; p++) {
                work[p] -= lower[lk + p] * x;
            }
        }
    }
}
