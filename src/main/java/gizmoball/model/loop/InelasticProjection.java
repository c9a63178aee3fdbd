package gizmoball.model.loop;

import java.util.Arrays;

/**
 * The compression step of a round of {@link NormalImpulses}: the nearest velocities that close on no row of the
 * cluster, perfectly inelastic, a projection found exactly on the impulses by Lawson and Hanson's active-set method,
 * or where rows depend on each other too much for it, by projected Gauss-Seidel. It keeps the impulses it found,
 * which the round's restitution reads.
 */
final class InelasticProjection {
    /** {@link LoopSettings#projectionSweeps()} and {@link LoopSettings#activeSetChanges()}: when it gives up. */
    private final int maxSweeps;
    private final int maxRounds;
    private final ContactRows contacts;
    private final ActiveRowsFactor factor;
    /** The rows and balls of the projection under way ({@link ContactRows#count()}, {@link ContactRows#balls()}). */
    private int balls;
    private int rows;
    // Kept from one projection to the next and grown to the largest cluster seen: a solve allocates nothing.
    private double[] impulse = new double[0];
    /** Per row: what it closes by before any impulse; the active set's trial impulses; a joining row's coupling. */
    private double[] base = new double[0];
    private double[] trial = new double[0];
    private double[] coupled = new double[0];
    /** Per row, the combination of the set's rows a joining row depends on ({@link #swapIn}). */
    private double[] combination = new double[0];
    private boolean[] active = new boolean[0];
    /** Per ball: the velocities the projection started from; a dependent row's residual ({@link #noAnswer}). */
    private double[] startX = new double[0];
    private double[] startY = new double[0];
    private double[] residualX = new double[0];
    private double[] residualY = new double[0];
    /** The velocities being projected, in place: the solve's own arrays. */
    private double[] vx;
    private double[] vy;

    InelasticProjection(ContactRows contacts, LoopSettings settings) {
        this.maxSweeps = settings.projectionSweeps();
        this.maxRounds = settings.activeSetChanges();
        this.contacts = contacts;
        this.factor = new ActiveRowsFactor(0, contacts::coupling);
    }

    /** The impulse on each row of the last projection (the array itself, which each projection overwrites). */
    double[] impulses() {
        return impulse;
    }

    /** Sizes the kept arrays for the rows and balls of the projection about to start. */
    private void room() {
        rows = contacts.count();
        balls = contacts.balls();
        if (impulse.length < rows) {
            impulse = new double[rows];
            base = new double[rows];
            trial = new double[rows];
            coupled = new double[rows];
            combination = new double[rows];
            active = new boolean[rows];
        }
        if (startX.length < balls) {
            startX = new double[balls];
            startY = new double[balls];
            residualX = new double[balls];
            residualY = new double[balls];
        }
    }

    /**
     * The impulses that make every row just not close, never pulling, from the current velocities: exactly by the
     * active-set method (iterative projections crawl where a ball is wedged between another and a wall at a tilt of
     * 1e-4, which needs impulses thousands of times its speed), else by projected Gauss-Seidel. Returns false if
     * neither finds velocities within the speed limit that close on nothing (surfaces closing a pocket). The
     * projection is unique in the velocities, so where the active set has found it beyond the limit, Gauss-Seidel,
     * converging to the same velocities, is not asked, nor where the active set has shown there is none: in a pocket
     * of 32 balls a flipper closed, its 500 sweeps over 74 rows cost a millisecond a tick to say so again.
     */
    boolean project(double[] vx, double[] vy, double speedLimit) {
        this.vx = vx;
        this.vy = vy;
        room();
        System.arraycopy(vx, 0, startX, 0, balls);
        System.arraycopy(vy, 0, startY, 0, balls);
        SetOutcome outcome = projectByActiveSet(speedLimit);
        if (outcome != SetOutcome.UNSETTLED) {
            return outcome == SetOutcome.SOLVED && withinLimit(vx, vy, speedLimit);
        }
        // Gauss-Seidel converges from any impulses that push: it starts where the active set got to (in a packed
        // pocket, a row depending on 48 others ends the active set with the rest of the answer found), unless those
        // impulses are past any a velocity within the limit needs (rows nearly dependent: 1e17).
        System.arraycopy(startX, 0, vx, 0, balls);
        System.arraycopy(startY, 0, vy, 0, balls);
        double bound = impulseBound(speedLimit);
        boolean warm = true;
        for (int i = 0; i < rows && warm; i++) {
            warm = impulse[i] >= 0 && impulse[i] <= bound;
        }
        for (int i = 0; i < rows; i++) {
            if (warm) {
                contacts.addImpulse(vx, vy, i, impulse[i]);
            } else {
                impulse[i] = 0;
            }
        }
        return projectBySweeps(speedLimit);
    }

    /** An impulse past which no velocity within the speed limit can need more: there is no answer. */
    private double impulseBound(double speedLimit) {
        return 4 * speedLimit * (rows + 1);
    }

    /**
     * Projected Gauss-Seidel (Hildreth's method), for the rare set of rows the active-set method does not settle
     * (rows that depend on each other in several ways): each row in turn takes the impulse that makes it just not
     * close, never pulling, until no impulse changes by more than rounding. It converges wherever an answer exists,
     * slowly where rows are nearly parallel; impulses past what any velocity within the speed limit needs mean
     * there is none.
     */
    private boolean projectBySweeps(double speedLimit) {
        double bound = impulseBound(speedLimit);
        double scale = 1;
        for (int k = 0; k < balls; k++) {
            scale = Math.max(scale, Math.abs(vx[k]) + Math.abs(vy[k]));
        }
        double tolerance = 1e-14 * scale;
        for (int sweep = 0; sweep < maxSweeps; sweep++) {
            double largest = 0;
            for (int i = 0; i < rows; i++) {
                double step = Math.max(-impulse[i], (contacts.closing(vx, vy, i) - ContactRows.SLOP) / contacts.diagonal(i));
                if (step != 0) {
                    impulse[i] += step;
                    contacts.addImpulse(vx, vy, i, step);
                    largest = Math.max(largest, Math.abs(step));
                    if (impulse[i] > bound) {
                        return false;
                    }
                }
            }
            if (largest <= tolerance) {
                return true;
            }
        }
        return false;
    }

    /**
     * Lawson and Hanson's active-set method for least squares with nonnegative unknowns, on the impulses: the row
     * closing fastest joins the set; the set's rows are solved as equalities exactly (each just not closing), on a
     * Cholesky factor of their coupling kept as rows join ({@link ActiveRowsFactor}); where that would make an impulse
     * pull, the impulses move only as far toward that answer as keeps every impulse pushing, and the row whose
     * impulse reaches zero leaves. Each step lowers the same convex objective, so the set never repeats, and the
     * method ends when no row outside the set closes. A joining row that depends on the set's rows (no impulse of its
     * own can change what it closes by) is swapped in for one that makes way ({@link #swapIn}).
     */
    private SetOutcome projectByActiveSet(double speedLimit) {
        for (int i = 0; i < rows; i++) {
            base[i] = contacts.closing(vx, vy, i);   // what each row closes by, before any impulse
        }
        Arrays.fill(active, 0, rows, false);
        factor.clear(rows);
        Arrays.fill(impulse, 0, rows, 0);
        for (int round = 0; round < maxRounds; round++) {
            int joining = -1;
            double most = ContactRows.SLOP;
            for (int i = 0; i < rows; i++) {
                if (active[i]) {
                    continue;
                }
                double closing = contacts.closing(vx, vy, i);
                if (closing > most) {
                    most = closing;
                    joining = i;
                }
            }
            if (joining < 0) {
                return activeRowsHold() ? SetOutcome.SOLVED : SetOutcome.UNSETTLED;
            }
            if (!factor.add(joining)) {
                Swap swap = swapIn(joining, speedLimit);
                if (swap != Swap.SWAPPED) {
                    return swap == Swap.NO_ROW_MAKES_WAY ? SetOutcome.INFEASIBLE : SetOutcome.UNSETTLED;
                }
            }
            active[joining] = true;
            for (int inner = 0; inner <= rows; inner++) {
                factor.solveKeeping(base, trial);
                double step = 1;
                for (int i = 0; i < rows; i++) {
                    if (active[i] && trial[i] <= 0) {
                        step = Math.min(step, impulse[i] <= 0 ? 0 : impulse[i] / (impulse[i] - trial[i]));
                    }
                }
                for (int i = 0; i < rows; i++) {
                    impulse[i] += step * (trial[i] - impulse[i]);
                }
                if (step == 1) {
                    break;
                }
                for (int i = 0; i < rows; i++) {
                    if (active[i] && impulse[i] <= 0) {
                        active[i] = false;
                        impulse[i] = 0;
                    }
                }
                if (!factor.keepOnly(active)) {
                    return SetOutcome.UNSETTLED;
                }
            }
            System.arraycopy(startX, 0, vx, 0, balls);
            System.arraycopy(startY, 0, vy, 0, balls);
            for (int i = 0; i < rows; i++) {
                if (impulse[i] != 0) {   // no impulse changes no velocity: a start never holds -0.0 for + 0.0 to turn
                    contacts.addImpulse(vx, vy, i, impulse[i]);
                }
            }
            if (!active[joining] || contacts.closing(vx, vy, joining) > ContactRows.SLOP) {
                return SetOutcome.UNSETTLED;   // a row depending on others that they cannot satisfy
            }
        }
        return SetOutcome.UNSETTLED;
    }

    /**
     * Whether no velocity within the speed limit satisfies both the set's rows and row j, where J_j = sum c_k J_k + r
     * with every c_k &lt;= 0: any v' whose rows close by no more than the slop has c_k J_k v' &lt;= c_k s_k + |c_k| slop,
     * so J_j v' &lt;= sum c_k s_k + slop sum |c_k| + |r| |v'|, and |v'| is at most the limit times the square root of
     * the number of balls. A row that only nearly depends on the set (r more than rounding: two balls side by side in
     * a slot that fits them to 1e-8 L) has an answer that needs large impulses, and this bound does not rule it out:
     * taken as none, a pocket of balls rang at no time apart to the collision cap (fuzz seed 13000553).
     */
    private boolean noAnswer(int joining, double[] c, double speedLimit) {
        double[] rx = residualX;
        double[] ry = residualY;
        Arrays.fill(rx, 0, balls, 0);
        Arrays.fill(ry, 0, balls, 0);
        contacts.addImpulse(rx, ry, joining, 1);
        double combined = 0;
        double weight = 0;
        for (int k = 0; k < rows; k++) {
            if (active[k] && c[k] != 0) {
                contacts.addImpulse(rx, ry, k, -c[k]);
                combined += c[k] * contacts.speed(k);
                weight += Math.abs(c[k]);
            }
        }
        double residual = 0;
        for (int k = 0; k < balls; k++) {
            residual += rx[k] * rx[k] + ry[k] * ry[k];
        }
        double margin = contacts.speed(joining) - combined;
        return margin > ContactRows.SLOP * (1 + weight) + Math.sqrt(residual) * speedLimit * Math.sqrt(balls);
    }

    /** How the active-set method ended. */
    private enum SetOutcome {
        /** Every row closes by no more than rounding: the projection. */
        SOLVED,
        /** No velocity within the limit closes on none of the rows ({@link #noAnswer}): surfaces close a pocket. */
        INFEASIBLE,
        /** Rows depend on each other in ways it does not settle: Gauss-Seidel takes them. */
        UNSETTLED
    }

    /** How a row depending on the set's rows joined it. */
    private enum Swap {
        SWAPPED,
        /** No row of the set can make way, and {@link #noAnswer} shows no velocity satisfies them all. */
        NO_ROW_MAKES_WAY,
        /**
         * No row can make way but the row only nearly depends on the set, or with a row out the set, the row in, does
         * not count as independent (rounding): Gauss-Seidel decides.
         */
        NOT_TAKEN
    }

    /**
     * A joining row that depends on the set's rows, J_j = sum of c_k J_k: impulse moved from the rows k with c_k &gt; 0
     * to it, in those proportions, changes no velocity, so it may move until the first of them reaches zero; that row
     * leaves and the joining row takes its place (the degenerate step of the simplex method). In a pocket packed with
     * balls there are more contacts than the balls can move in ways (3 per ball, in 2 dimensions), and a row joining
     * late depends on the others. Where no row of the set has c_k &gt; 0, there may be no answer ({@link #noAnswer});
     * else the set is given up to Gauss-Seidel. The impulses are left as they were unless the row is swapped in.
     */
    private Swap swapIn(int joining, double speedLimit) {
        for (int i = 0; i < rows; i++) {
            coupled[i] = active[i] ? contacts.coupling(i, joining) : 0;
        }
        double[] c = combination;
        factor.solve(coupled, c);
        int leaving = -1;
        double step = Double.POSITIVE_INFINITY;
        for (int i = 0; i < rows; i++) {
            if (active[i] && c[i] > 0 && impulse[i] / c[i] < step) {
                step = impulse[i] / c[i];
                leaving = i;
            }
        }
        if (leaving < 0) {
            return noAnswer(joining, c, speedLimit) ? Swap.NO_ROW_MAKES_WAY : Swap.NOT_TAKEN;
        }
        active[leaving] = false;
        if (!factor.keepOnly(active) || !factor.add(joining)) {
            return Swap.NOT_TAKEN;   // the caller gives up the set
        }
        for (int i = 0; i < rows; i++) {
            if (active[i]) {
                impulse[i] = Math.max(0, impulse[i] - step * c[i]);
            }
        }
        impulse[leaving] = 0;
        impulse[joining] = step;
        return Swap.SWAPPED;
    }

    /**
     * Whether every row, those solved as equalities too, closes by no more than rounding. Rows that nearly depend on
     * each other in a way no velocity satisfies (a ball between a flipper's tip, a floor and a ball against a wall)
     * can give impulses of 1e17 whose rounding alone moves the velocities by 16 L/s: an answer only in name, which left
     * the rows closing, was met again at once, 400 times a tick.
     */
    private boolean activeRowsHold() {
        for (int i = 0; i < rows; i++) {
            if (contacts.closing(vx, vy, i) > Tolerances.ROUNDING_SPEED) {
                return false;
            }
        }
        return true;
    }

    /** Whether every ball's speed is within {@code limit}. */
    boolean withinLimit(double[] vx, double[] vy, double limit) {
        for (int k = 0; k < contacts.balls(); k++) {
            if (Math.sqrt(vx[k] * vx[k] + vy[k] * vy[k]) > limit) {
                return false;
            }
        }
        return true;
    }
}
