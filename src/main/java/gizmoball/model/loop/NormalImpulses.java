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
 *     close on no contact, perfectly inelastic: a projection ({@link InelasticProjection}), found exactly on the
 *     impulses by Lawson and Hanson's active-set method, or where rows depend on each other too much for it, by
 *     projected Gauss-Seidel;</li>
 * <li>restitution: in a round where something closes faster than an impact, the contacts whose compression
 *     impulse is a real impact get that impulse again times one coefficient for the round (Poisson's law), their
 *     coefficients averaged by impulse, so a single contact bounces exactly as the reflect methods say. One
 *     coefficient, because coefficients that differ turn the nearly opposite impulses of a narrow wedge (a ball
 *     struck into it at 20 L/s meets each side with some 570) into a kick across it, where one sends the ball
 *     straight back out.</li>
 * </ol>
 * The restitution of one contact can close another (a ball sent back into the one behind it): the next round takes
 * it, until no contact closes faster than rounding. A round after the first whose compression stops every ball dead
 * is a jammed cluster (balls filling a pocket): it ends at rest; so does, after {@link LoopSettings#impactRounds()} rounds, what
 * still rings.
 * A projection onto a convex set that holds the still velocities never adds kinetic energy, and with one coefficient
 * for every contact of still surfaces a round's restitution keeps it exactly (the compression impulse is orthogonal to
 * the compressed velocity). Where contacts that only settled in the round make the restitution add energy, it is
 * scaled back.
 * Where swinging surfaces leave no velocity within the speed limit that closes on none of the rows, the
 * cluster is infeasible: the caller stalls those surfaces and solves again.
 */
final class NormalImpulses {
    /** {@link LoopSettings#impactRounds()}, {@link LoopSettings#ringMatch()}. */
    private final int maxImpactRounds;
    private final double ringMatch;
    private final ContactRows contacts = new ContactRows();
    private final InelasticProjection projection;
    private int balls;
    private int rows;
    // Kept from one solve to the next and grown to the largest cluster seen: a solve allocates nothing.
    /** Per row: the coefficient a real impact on it bounces with; the largest compression impulse it took. */
    private double[] restitution = new double[0];
    private double[] largest = new double[0];
    /** Per ball: the velocities being solved; a round's compressed ones and its restitution impulses. */
    private double[] vx = new double[0];
    private double[] vy = new double[0];
    private double[] cx = new double[0];
    private double[] cy = new double[0];
    private double[] rx = new double[0];
    private double[] ry = new double[0];
    /** The velocities each of the last three rounds started from, round r's at r % 3: the cycle check's. */
    private final double[][] startX = new double[3][0];
    private final double[][] startY = new double[3][0];

    /** @param settings the loop's tuning: how many rounds of impacts, and when the projection gives up */
    NormalImpulses(LoopSettings settings) {
        this.maxImpactRounds = settings.impactRounds();
        this.ringMatch = settings.ringMatch();
        this.projection = new InelasticProjection(contacts, settings);
    }

    /** Starts a new cluster of {@code balls} balls, with no rows yet. */
    void clear(int balls) {
        this.balls = balls;
        this.rows = 0;
        contacts.clear(balls);
        if (vx.length < balls) {
            vx = new double[balls];
            vy = new double[balls];
            cx = new double[balls];
            cy = new double[balls];
            rx = new double[balls];
            ry = new double[balls];
            for (int r = 0; r < 3; r++) {
                startX[r] = new double[balls];
                startY[r] = new double[balls];
            }
        }
    }

    /**
     * Adds a contact row: {@code (v_a - v_b) . n >= speed}.
     *
     * @param a           the ball the normal points into
     * @param b           the other ball, or -1 for a surface
     * @param nx          the unit normal (from {@code b} or the surface toward {@code a})
     * @param speed       the surface's speed along the normal (0 for a ball or a still surface)
     * @param restitution the coefficient a real impact on it bounces with
     */
    void row(int a, int b, double nx, double ny, double speed, double restitution) {
        contacts.add(a, b, nx, ny, speed);
        if (rows == this.restitution.length) {
            this.restitution = Arrays.copyOf(this.restitution, Math.max(8, 2 * rows));
            largest = new double[this.restitution.length];
        }
        this.restitution[rows++] = restitution;
    }

    /**
     * What the solve found: the balls' velocities; for each row the largest compression impulse it took in any round
     * of impacts (above the impact impulse: a real impact); whether every round had an answer within the speed limit;
     * how many rounds it took (what its cost grows with). The arrays are the solve's own, longer than the balls and
     * rows where it has seen a larger cluster, and the next solve overwrites them.
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
     * Most ring in a cycle of two: a ball between two contacts that touch it on both sides is sent from one into the
     * other and back (in a box packed with 31 elastic balls, rounds 5 to 256 alternated between two states to 2e-13
     * L/s; in a pocket of 32 balls a flipper pressed on, to 7e-10 L/s; where the two contacts are not quite opposite,
     * each bounce turns a little of the speed, and two balls in a slot that fits them, their normal tilted by 3e-5,
     * drift by some 3e-5 of the speed every two rounds). A round that starts where the round two before it started, to
     * within {@link LoopSettings#ringMatch()} of the fastest ball's speed, would ring so to the cap; on a round of the
     * cap's parity it ends there, at the limit the cap would have given it, moved by the drift the cap left it (about
     * 0.4% of the speed for that slot).
     */
    Result solve(double[] vx0, double[] vy0, double[] impact, double speedLimit) {
        System.arraycopy(vx0, 0, vx, 0, balls);
        System.arraycopy(vy0, 0, vy, 0, balls);
        Arrays.fill(largest, 0, rows, 0);
        int round = 0;
        for (; round < maxImpactRounds; round++) {
            if (!anyClosing()) {
                return new Result(vx, vy, largest, projection.withinLimit(vx, vy, speedLimit), round);
            }
            if ((maxImpactRounds - round) % 2 == 0 && round >= 2) {
                double tolerance = ringMatch * Math.max(1, fastest(vx, vy));
                if (within(startX[(round - 2) % 3], vx, tolerance) && within(startY[(round - 2) % 3], vy, tolerance)) {
                    break;
                }
            }
            double[] before = startX[round % 3];
            double[] beforeY = startY[round % 3];
            System.arraycopy(vx, 0, before, 0, balls);
            System.arraycopy(vy, 0, beforeY, 0, balls);
            // A round in which nothing closes faster than an impact is a settling, not an impact: it comes to rest
            // however large the impulses (a ball sliding past another at a tilt of 1e-4 meets it at 1e-4 of its speed).
            boolean impacts = anyClosingFaster(impact);
            if (!projection.project(vx, vy, speedLimit)) {
                boolean restSatisfies = restSatisfiesEveryRow();
                if (restSatisfies) {
                    restWhereClosing(before, beforeY, speedLimit);
                }
                return new Result(vx, vy, largest, restSatisfies, round + 1);
            }
            double[] impulse = projection.impulses();
            System.arraycopy(vx, 0, cx, 0, balls);
            System.arraycopy(vy, 0, cy, 0, balls);
            if (round > 0 && still(cx, cy)) {
                // Sent back by its last round's restitution into contacts that stop it dead again: the cluster is
                // jammed (balls filling a pocket), and bounce after bounce would ring in place for ever. Its limit
                // is rest.
                return new Result(vx, vy, largest, true, round + 1);
            }
            Arrays.fill(rx, 0, balls, 0);
            Arrays.fill(ry, 0, balls, 0);
            double weighted = 0;
            double total = 0;
            for (int i = 0; i < rows; i++) {
                largest[i] = Math.max(largest[i], impulse[i] * contacts.diagonal(i));
                if (impacts && impulse[i] * contacts.diagonal(i) > impact[i]) {
                    weighted += restitution[i] * impulse[i];
                    total += impulse[i];
                    contacts.addImpulse(rx, ry, i, impulse[i]);
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
        boolean feasible = projection.project(vx, vy, speedLimit) && projection.withinLimit(vx, vy, speedLimit);
        return new Result(vx, vy, largest, feasible, round + 1);
    }

    /**
     * Whether the balls at rest close on no row: no surface moves toward its ball (a still surface, a ball beyond the
     * cluster pressing in, a moving shape stalled). Then the projection exists, however badly its rows are
     * conditioned.
     */
    private boolean restSatisfiesEveryRow() {
        for (int i = 0; i < rows; i++) {
            if (contacts.speed(i) > 0) {
                return false;
            }
        }
        return true;
    }

    /**
     * Where neither the active set nor Gauss-Seidel found the projection though it exists: rows so nearly dependent
     * (a pocket packed with 32 balls, 47 rows) that the exact solve leaves them closing at 3e-9 L/s and 500 sweeps at
     * 4e-5 L/s, so the cluster would meet itself again at no time apart to the collision cap (fuzz seed 1000117, 400
     * solves in one tick). What the sweeps reached is kept where it closes on nothing, if it holds no more kinetic
     * energy than the round began with (else the round's start is); every ball of a row still closing stops, and so
     * on until none closes: at rest the rows hold ({@link #restSatisfiesEveryRow}), so it ends with the cluster
     * jammed where it closed, as a pocket packed with balls is, and the energy never grows.
     */
    private void restWhereClosing(double[] fromX, double[] fromY, double speedLimit) {
        if (!(kinetic(vx, vy) <= kinetic(fromX, fromY)) || !projection.withinLimit(vx, vy, speedLimit)) {
            System.arraycopy(fromX, 0, vx, 0, balls);
            System.arraycopy(fromY, 0, vy, 0, balls);
        }
        boolean stopped = true;
        while (stopped) {
            stopped = false;
            for (int i = 0; i < rows; i++) {
                if (contacts.closing(vx, vy, i) > ContactRows.SLOP) {
                    stopped |= contacts.rest(vx, vy, i);
                }
            }
        }
    }

    /** Twice the kinetic energy of unit masses at (x, y); NaN where a velocity is not finite. */
    private double kinetic(double[] x, double[] y) {
        double sum = 0;
        for (int k = 0; k < balls; k++) {
            sum += x[k] * x[k] + y[k] * y[k];
        }
        return sum;
    }

    /** The largest speed among the balls, as |vx| + |vy|. */
    private double fastest(double[] x, double[] y) {
        double most = 0;
        for (int k = 0; k < balls; k++) {
            most = Math.max(most, Math.abs(x[k]) + Math.abs(y[k]));
        }
        return most;
    }

    /** Whether every component of {@code x} lies within {@code tolerance} of the same one of {@code y}. */
    private boolean within(double[] x, double[] y, double tolerance) {
        for (int k = 0; k < balls; k++) {
            if (Math.abs(x[k] - y[k]) > tolerance) {
                return false;
            }
        }
        return true;
    }

    private boolean still(double[] x, double[] y) {
        for (int k = 0; k < balls; k++) {
            if (Math.abs(x[k]) > ContactRows.SLOP || Math.abs(y[k]) > ContactRows.SLOP) {
                return false;
            }
        }
        return true;
    }

    private boolean anyClosing() {
        for (int i = 0; i < rows; i++) {
            if (contacts.closing(vx, vy, i) > ContactRows.SLOP) {
                return true;
            }
        }
        return false;
    }

    private boolean anyClosingFaster(double[] than) {
        for (int i = 0; i < rows; i++) {
            if (contacts.closing(vx, vy, i) > than[i]) {
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
            if (contacts.speed(i) != 0) {
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
}
