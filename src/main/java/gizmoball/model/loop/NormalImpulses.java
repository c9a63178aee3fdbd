package gizmoball.model.loop;

import java.util.Arrays;

/**
 * The simultaneous normal impulses of one contact cluster (docs/design.md, "Contact clusters"): balls of equal mass,
 * no spin, frictionless contacts, each contact a row {@code (v_a - v_b) . n >= s} on the balls' velocities, where
 * {@code b} is another ball of the cluster or a surface ({@code s} its own speed along {@code n}: zero for a still
 * one, the surface speed of a swinging one, which gives velocity and takes none).
 *
 * <p>The answer comes in rounds of impacts. Each round is two steps:
 * <ol>
 * <li>compression: the nearest velocities (in the kinetic-energy metric, for equal masses the Euclidean one) that
 *     close on no contact, perfectly inelastic: a projection, found exactly on the impulses by Lawson and Hanson's
 *     active-set method, or where rows depend on each other too much for it, by projected Gauss-Seidel;</li>
 * <li>restitution: in a round where something closes faster than an impact, the contacts whose compression
 *     impulse is a real impact get that impulse again times one coefficient for the round (Poisson's law), their
 *     coefficients averaged by impulse, so a single contact bounces exactly as the reflect methods say. One
 *     coefficient, because coefficients that differ turn the nearly opposite impulses of a narrow wedge (a ball
 *     struck into it at 20 L/s meets each side with some 570) into a kick across it, where one sends the ball
 *     straight back out.</li>
 * </ol>
 * The restitution of one contact can close another (a ball sent back into the one behind it): the next round takes
 * it, until no contact closes faster than rounding. A round after the first whose compression stops every ball dead
 * is a jammed cluster (balls filling a pocket): it ends at rest; so does, after {@link #MAX_IMPACT_ROUNDS} rounds, what
 * still rings.
 * A projection onto a convex set that holds the still velocities never adds kinetic energy, and with one coefficient
 * for every contact of still surfaces a round's restitution keeps it exactly (the compression impulse is orthogonal to
 * the compressed velocity). Where contacts that only settled in the round make the restitution add energy, it is
 * scaled back.
 * Where swinging surfaces leave no velocity within the speed limit that closes on none of the rows, the
 * cluster is infeasible: the caller stalls those surfaces and solves again.
 */
final class NormalImpulses {
    /**
     * Rounds of impacts after which what still closes takes the impact inelastically: far more than a row of
     * {@link ContactCluster#MAX_BALLS} touching balls needs to pass an impact along and back. Only balls ringing in a
     * pocket they nearly fill go on longer; their limit, with any loss at all, is rest.
     */
    private static final int MAX_IMPACT_ROUNDS = 256;
    /**
     * Relative to the fastest ball's speed, how near a round's start must be to the start two rounds before for the
     * rounds to count as a cycle of two: rounding's scale, far below any change a round of impacts makes.
     */
    private static final double CYCLE_MATCH = 1e-9;
    /**
     * Sweeps of projected Gauss-Seidel before it counts as not converging: it is the fallback for rows the active set
     * cannot settle, and at 10,000 sweeps a cluster of 30 balls cost half a second of one tick.
     */
    private static final int MAX_SWEEPS = 500;
    /** Changes of the active set before the solve counts as not settling (each adds or drops one row). */
    private static final int MAX_ROUNDS = 200;
    /**
     * L/s: a row closing no faster than this is left alone, as the detector leaves a touch closing slower than
     * {@link Tolerances#ROUNDING_SPEED}: the rounding of a normal that is nearly square to a motion (two balls side by
     * side in a gap that fits them, one sliding past the other) asks for impulses without end to undo it.
     */
    private static final double SLOP = Tolerances.ROUNDING_SPEED / 2;

    private final int balls;
    private final int rows;
    private final int[] a;
    private final int[] b;
    private final double[] nx;
    private final double[] ny;
    private final double[] speed;
    private final double[] restitution;
    private final double[] impulse;
    private double[] vx;
    private double[] vy;

    /**
     * @param a           per row, the ball the normal points into
     * @param b           per row, the other ball, or -1 for a surface
     * @param nx          per row, the unit normal (from {@code b} or the surface toward {@code a})
     * @param speed       per row, the surface's speed along the normal (0 for a ball or a still surface)
     * @param restitution per row, the coefficient a real impact on it bounces with
     */
    NormalImpulses(int balls, int[] a, int[] b, double[] nx, double[] ny, double[] speed, double[] restitution) {
        this.balls = balls;
        this.rows = a.length;
        this.a = a;
        this.b = b;
        this.nx = nx;
        this.ny = ny;
        this.speed = speed;
        this.restitution = restitution;
        this.impulse = new double[rows];
    }

    /**
     * What the solve found: the balls' velocities; for each row the largest compression impulse it took in any round
     * of impacts (above the impact impulse: a real impact); whether every round had an answer within the speed limit;
     * how many rounds it took (what its cost grows with).
     */
    record Result(double[] vx, double[] vy, double[] compression, boolean feasible, int rounds) {
    }

    /**
     * Solves for the balls' velocities after the cluster's impacts, in rounds: each round compresses every closing
     * contact at once and gives each real impact its restitution; a round's restitution can close another contact
     * (a ball sent back into the one behind it), which the next round takes, until no contact closes. So a row of
     * touching elastic balls driven into a wall passes the impact along and comes back whole, as a Newton's cradle
     * does. {@code impact}: per row, the change of its closing speed above which its compression is an impact that
     * bounces; below it the contact comes to rest (restitution 0).
     *
     * <p>Rounds that ring for ever end at the limit the cap gives them, the inelastic projection of where they are.
     * Some ring in a cycle of two: a ball between two contacts that touch it on both sides is sent from one into the
     * other and back (in a box packed with 31 elastic balls, rounds 5 to 256 alternated between two states to 2e-13
     * L/s; in a pocket of 32 balls a flipper pressed on, to 7e-10 L/s, drifting by that much every two rounds). A round
     * that starts where the round two before it started, to within {@link #CYCLE_MATCH} of the fastest ball's speed,
     * would ring so to the cap; on a round of the cap's parity it ends there, in the state the cap would have met (to
     * that drift, some 1e-7 of the speeds).
     */
    Result solve(double[] vx0, double[] vy0, double[] impact, double speedLimit) {
        vx = vx0.clone();
        vy = vy0.clone();
        double[] largest = new double[rows];
        double[] lastX = null;
        double[] lastY = null;
        double[] twoBackX = null;
        double[] twoBackY = null;
        int round = 0;
        for (; round < MAX_IMPACT_ROUNDS; round++) {
            if (!anyClosing()) {
                return new Result(vx, vy, largest, withinLimit(speedLimit), round);
            }
            if ((MAX_IMPACT_ROUNDS - round) % 2 == 0 && twoBackX != null) {
                double tolerance = CYCLE_MATCH * Math.max(1, fastest(vx, vy));
                if (within(twoBackX, vx, tolerance) && within(twoBackY, vy, tolerance)) {
                    break;
                }
            }
            double[] before = vx.clone();
            double[] beforeY = vy.clone();
            twoBackX = lastX;
            twoBackY = lastY;
            lastX = before;
            lastY = beforeY;
            // A round in which nothing closes faster than an impact is a settling, not an impact: it comes to rest
            // however large the impulses (a ball sliding past another at a tilt of 1e-4 meets it at 1e-4 of its speed).
            boolean impacts = anyClosingFaster(impact);
            if (!project(speedLimit)) {
                return new Result(vx, vy, largest, false, round + 1);
            }
            double[] cx = vx.clone();
            double[] cy = vy.clone();
            if (round > 0 && still(cx, cy)) {
                // Sent back by its last round's restitution into contacts that stop it dead again: the cluster is
                // jammed (balls filling a pocket), and bounce after bounce would ring in place for ever. Its limit
                // is rest.
                return new Result(vx, vy, largest, true, round + 1);
            }
            double[] rx = new double[balls];
            double[] ry = new double[balls];
            double weighted = 0;
            double total = 0;
            for (int i = 0; i < rows; i++) {
                largest[i] = Math.max(largest[i], impulse[i] * diagonal(i));
                if (impacts && impulse[i] * diagonal(i) > impact[i]) {
                    weighted += restitution[i] * impulse[i];
                    total += impulse[i];
                    addImpulse(rx, ry, i, impulse[i]);
                }
            }
            double e = total > 0 ? weighted / total : 0;
            for (int k = 0; k < balls; k++) {
                rx[k] *= e;
                ry[k] *= e;
            }
            double scale = energyKeepingScale(before, beforeY, cx, cy, rx, ry);
            for (int k = 0; k < balls; k++) {
                vx[k] = cx[k] + scale * rx[k];
                vy[k] = cy[k] + scale * ry[k];
            }
        }
        boolean feasible = project(speedLimit) && withinLimit(speedLimit);
        return new Result(vx, vy, largest, feasible, round + 1);
    }

    /** The largest speed among the balls, as |vx| + |vy|. */
    private static double fastest(double[] x, double[] y) {
        double most = 0;
        for (int k = 0; k < x.length; k++) {
            most = Math.max(most, Math.abs(x[k]) + Math.abs(y[k]));
        }
        return most;
    }

    /** Whether every component of {@code x} lies within {@code tolerance} of the same one of {@code y}. */
    private static boolean within(double[] x, double[] y, double tolerance) {
        for (int k = 0; k < x.length; k++) {
            if (Math.abs(x[k] - y[k]) > tolerance) {
                return false;
            }
        }
        return true;
    }

    private boolean still(double[] x, double[] y) {
        for (int k = 0; k < balls; k++) {
            if (Math.abs(x[k]) > SLOP || Math.abs(y[k]) > SLOP) {
                return false;
            }
        }
        return true;
    }

    /** How much one unit of impulse on the row changes what it closes by: 1 on a surface, 2 between two balls. */
    private double diagonal(int i) {
        return b[i] < 0 ? 1 : 2;
    }

    private boolean anyClosing() {
        for (int i = 0; i < rows; i++) {
            if (speed[i] - relative(i) > SLOP) {
                return true;
            }
        }
        return false;
    }

    private boolean anyClosingFaster(double[] than) {
        for (int i = 0; i < rows; i++) {
            if (speed[i] - relative(i) > than[i]) {
                return true;
            }
        }
        return false;
    }

    /**
     * Where every surface is still, the scale of the restitution impulses (at most 1) that adds no kinetic energy:
     * |c + s r|^2 <= |v0|^2, which holds at s = 0 since compression never adds energy. With a swinging surface the
     * surface does work, and the impulses stand as they are.
     */
    private double energyKeepingScale(double[] vx0, double[] vy0, double[] cx, double[] cy, double[] rx,
                                      double[] ry) {
        for (int i = 0; i < rows; i++) {
            if (speed[i] != 0) {
                return 1;
            }
        }
        double before = 0;
        double cc = 0;
        double cr = 0;
        double rr = 0;
        for (int k = 0; k < balls; k++) {
            before += vx0[k] * vx0[k] + vy0[k] * vy0[k];
            cc += cx[k] * cx[k] + cy[k] * cy[k];
            cr += cx[k] * rx[k] + cy[k] * ry[k];
            rr += rx[k] * rx[k] + ry[k] * ry[k];
        }
        if (rr == 0 || cc + 2 * cr + rr <= before) {
            return 1;
        }
        // The positive root of rr s^2 + 2 cr s + (cc - before) = 0; cc <= before, so it exists and lies in [0, 1).
        double root = (-cr + Math.sqrt(Math.max(0, cr * cr - rr * (cc - before)))) / rr;
        return Math.max(0, Math.min(1, root));
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
    private boolean project(double speedLimit) {
        double[] vx0 = vx.clone();
        double[] vy0 = vy.clone();
        SetOutcome outcome = projectByActiveSet(speedLimit);
        if (outcome != SetOutcome.UNSETTLED) {
            return outcome == SetOutcome.SOLVED && withinLimit(speedLimit);
        }
        // Gauss-Seidel converges from any impulses that push: it starts where the active set got to (in a packed
        // pocket, a row depending on 48 others ends the active set with the rest of the answer found), unless those
        // impulses are past any a velocity within the limit needs (rows nearly dependent: 1e17).
        System.arraycopy(vx0, 0, vx, 0, balls);
        System.arraycopy(vy0, 0, vy, 0, balls);
        double bound = impulseBound(speedLimit);
        boolean warm = true;
        for (int i = 0; i < rows && warm; i++) {
            warm = impulse[i] >= 0 && impulse[i] <= bound;
        }
        for (int i = 0; i < rows; i++) {
            if (warm) {
                addImpulse(vx, vy, i, impulse[i]);
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
        for (int sweep = 0; sweep < MAX_SWEEPS; sweep++) {
            double largest = 0;
            for (int i = 0; i < rows; i++) {
                double step = Math.max(-impulse[i], (speed[i] - relative(i) - SLOP) / diagonal(i));
                if (step != 0) {
                    impulse[i] += step;
                    addImpulse(vx, vy, i, step);
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
        double[] base = new double[rows];
        for (int i = 0; i < rows; i++) {
            base[i] = speed[i] - relative(i);   // what each row closes by, before any impulse
        }
        double[] vx0 = vx.clone();
        double[] vy0 = vy.clone();
        boolean[] active = new boolean[rows];
        ActiveRowsFactor factor = new ActiveRowsFactor(rows, this::coupling);
        Arrays.fill(impulse, 0);
        double[] trial = new double[rows];
        for (int round = 0; round < MAX_ROUNDS; round++) {
            int joining = -1;
            double most = SLOP;
            for (int i = 0; i < rows; i++) {
                double closing = speed[i] - relative(i);
                if (!active[i] && closing > most) {
                    most = closing;
                    joining = i;
                }
            }
            if (joining < 0) {
                return activeRowsHold() ? SetOutcome.SOLVED : SetOutcome.UNSETTLED;
            }
            if (!factor.add(joining)) {
                Swap swap = swapIn(joining, active, factor, speedLimit);
                if (swap != Swap.SWAPPED) {
                    return swap == Swap.NO_ROW_MAKES_WAY ? SetOutcome.INFEASIBLE : SetOutcome.UNSETTLED;
                }
            }
            active[joining] = true;
            for (int inner = 0; inner <= rows; inner++) {
                factor.solve(base, trial);
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
            System.arraycopy(vx0, 0, vx, 0, balls);
            System.arraycopy(vy0, 0, vy, 0, balls);
            for (int i = 0; i < rows; i++) {
                addImpulse(vx, vy, i, impulse[i]);
            }
            if (!active[joining] || speed[joining] - relative(joining) > SLOP) {
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
    private boolean noAnswer(int joining, double[] c, boolean[] active, double speedLimit) {
        double[] rx = new double[balls];
        double[] ry = new double[balls];
        addImpulse(rx, ry, joining, 1);
        double combined = 0;
        double weight = 0;
        for (int k = 0; k < rows; k++) {
            if (active[k] && c[k] != 0) {
                addImpulse(rx, ry, k, -c[k]);
                combined += c[k] * speed[k];
                weight += Math.abs(c[k]);
            }
        }
        double residual = 0;
        for (int k = 0; k < balls; k++) {
            residual += rx[k] * rx[k] + ry[k] * ry[k];
        }
        double margin = speed[joining] - combined;
        return margin > SLOP * (1 + weight) + Math.sqrt(residual) * speedLimit * Math.sqrt(balls);
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
    private Swap swapIn(int joining, boolean[] active, ActiveRowsFactor factor, double speedLimit) {
        double[] coupled = new double[rows];
        for (int i = 0; i < rows; i++) {
            coupled[i] = active[i] ? coupling(i, joining) : 0;
        }
        double[] c = new double[rows];
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
            return noAnswer(joining, c, active, speedLimit) ? Swap.NO_ROW_MAKES_WAY : Swap.NOT_TAKEN;
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
            if (speed[i] - relative(i) > Tolerances.ROUNDING_SPEED) {
                return false;
            }
        }
        return true;
    }

    /** J_i . J_j: how an impulse on row j changes what row i closes by. */
    private double coupling(int i, int j) {
        double dot = nx[i] * nx[j] + ny[i] * ny[j];
        double sum = 0;
        if (a[i] == a[j]) {
            sum += dot;
        }
        if (b[i] >= 0 && b[i] == a[j]) {
            sum -= dot;
        }
        if (b[j] >= 0 && a[i] == b[j]) {
            sum -= dot;
        }
        if (b[i] >= 0 && b[i] == b[j]) {
            sum += dot;
        }
        return sum;
    }

    private double relative(int i) {
        double ux = vx[a[i]];
        double uy = vy[a[i]];
        if (b[i] >= 0) {
            ux -= vx[b[i]];
            uy -= vy[b[i]];
        }
        return ux * nx[i] + uy * ny[i];
    }

    private void addImpulse(double[] x, double[] y, int i, double amount) {
        x[a[i]] += amount * nx[i];
        y[a[i]] += amount * ny[i];
        if (b[i] >= 0) {
            x[b[i]] -= amount * nx[i];
            y[b[i]] -= amount * ny[i];
        }
    }

    private boolean withinLimit(double limit) {
        for (int k = 0; k < balls; k++) {
            if (Math.sqrt(vx[k] * vx[k] + vy[k] * vy[k]) > limit) {
                return false;
            }
        }
        return true;
    }
}
