package gizmoball.model.loop;

import java.util.Arrays;
import java.util.List;

/**
 * Stage 3 over the whole board: the earliest collision of any awake ball within the time left in the tick. It keeps
 * each ball's earliest collision with the scene (walls and gizmos) and with the other balls, in seconds since the
 * tick began, so that after a collision only the balls it changed are asked again, not every ball against
 * everything. What a collision changes is forgotten by the loop: the balls involved; the balls that can reach a
 * moving shape a trigger turned round; everything when another trigger, a capture, a launch, a wake-up or a held
 * flipper changes the scene. Ball pairs come from a
 * {@link BallGrid}, so a ball is asked only about the balls it can reach.
 * <p>Over 400 lines because the schedule and its forgetting are one job whose parts share its arrays, every tick.
 */
final class CollisionSchedule {
    private final CollisionDetector detector;
    /**
     * Each free ball's known collisions, by its slot ({@link Ball#slot()}): whether it is known (not: ask again), and
     * what the slot's ball meets then (null: none), as it was found; its time is {@code sceneAt} and {@code ballsAt}
     * below. No {@link Collision} is made until {@link #next} gives the earliest.
     */
    private boolean[] sceneKnown = new boolean[0];
    private boolean[] ballsKnown = new boolean[0];
    private Contact[] withScene = new Contact[0];
    private Contact[] withBalls = new Contact[0];
    /**
     * When each known collision comes and what it meets, side by side: {@code at} in seconds since the tick began
     * (positive infinity: none) and whether it is with a circle.
     */
    private double[] sceneAt = new double[0];
    private boolean[] sceneCircle = new boolean[0];
    private double[] ballsAt = new double[0];
    private boolean[] ballsCircle = new boolean[0];
    /** The filed balls by slot. */
    private Ball[] bySlot = new Ball[0];
    /**
     * The slots with a collision not known, a bit each (slot s is bit s % 64 of word s / 64): only they are asked
     * again, in slot order, which reading the bits gives without sorting.
     */
    private long[] unknown = new long[0];
    /**
     * The awake balls' slots in board order, found again after the awake balls change (slot order too, but for balls
     * filed since the tick's filing, which take the next slots).
     */
    private int[] awakeSlots = new int[0];
    private int awakeCount;
    private boolean[] isAwake = new boolean[0];
    /** Each awake slot's place in {@link #awakeSlots}. */
    private int[] awakeIndex = new int[0];
    /**
     * By place in {@link #awakeSlots}: the earliest {@code at} of that ball's known collisions, side by side, so that
     * the search reads a block's balls from a few cache lines and goes to a ball's own books only for an offer that
     * may be taken (at 200 balls, a fifth off the time of a search, which read them through the slots).
     */
    private double[] placeEarliest = new double[0];
    private boolean awakeStale = true;
    /**
     * The awake balls in blocks of {@link #blockSize} consecutive places of {@link #awakeSlots}, each with the earliest
     * {@code at} of its balls' known collisions (found again when one of them changed): the search for the earliest
     * collision passes over a block that cannot hold a better one, so a collision among 200 awake balls reads a few
     * blocks, not 400 known collisions.
     */
    private double[] blockEarliest = new double[0];
    private boolean[] blockStale = new boolean[0];
    /** {@link LoopSettings#scheduleBlock()}. */
    private final int blockSize;
    private final NearTies best = new NearTies();
    /** What {@link #next} found, set afresh by each search (read before the next). */
    private final Collision found = new Collision();
    /**
     * By slot, the slots whose known ball collision has been with that ball (some since replaced): forgetting a ball
     * looks only at those, not at every ball.
     */
    private int[][] pointedAtBy = new int[0][];
    private int[] pointedAtCount = new int[0];
    /** By slot: whether the ball was taken out of play (captured) since it was filed: its cell no longer holds it. */
    private boolean[] taken = new boolean[0];
    private int filed;
    private final BallGrid grid;
    /** The filed balls' centres and motions, by slot: where a filed ball keeps its centre until the tick ends. */
    private final Motions motions;
    /** One pair's search, asked again for every ball near the one asking (its collision is made only when found). */
    private final Earliest pair = new Earliest(0);
    /** The search of one asking ball against the balls near it. */
    private final Earliest againstBalls = new Earliest(0);
    /** Seconds since the tick began at which it ends: each filing sweeps a ball's box until then. */
    private double until;
    /** The highest speed of any ball since the balls were filed (the pair test's bound, with the asking ball's). */
    private double fastest;

    CollisionSchedule(CollisionDetector detector, BallGrid grid, Motions motions, LoopSettings settings) {
        this.detector = detector;
        this.grid = grid;
        this.motions = motions;
        this.blockSize = settings.scheduleBlock();
    }

    /**
     * A tick of {@code seconds} starts: no ball is filed (a ball forgotten before the first filing is not filed).
     */
    void begin(double seconds) {
        unfile();
        until = seconds;
        awakeStale = true;
    }

    /**
     * The filing is over (its tick ended, or a new filing begins): each filed ball keeps its centre itself again, and no
     * ball is filed.
     */
    void unfile() {
        for (int slot = 0; slot < filed; slot++) {
            bySlot[slot].unfile();
        }
        filed = 0;
        motions.clear();
    }

    /**
     * Files every free ball (awake or asleep) where it is now, {@code elapsed} seconds into a tick that ends
     * {@code tickEnd} seconds after it began; every known collision is forgotten. The books are kept from filing to
     * filing, and from tick to tick, grown when the balls outgrow them.
     */
    void file(List<Ball> free, double elapsed, double tickEnd) {
        int n = free.size();
        unfile();
        grid.clear(n, motions);
        until = tickEnd;
        fastest = 0;
        if (bySlot.length < n) {
            grow(Math.max(n, 2 * bySlot.length));
        }
        for (int i = 0; i < n; i++) {   // by index: an iterator would be made at every filing
            Ball ball = free.get(i);
            bySlot[filed] = ball;
            ball.file(motions, filed++);
            fileSweep(ball, elapsed, true);
        }
        forgetAll();
        awakeStale = true;
    }

    /** Books for {@code n} balls, what they know kept (a ball freed in the tick is added to them). */
    private void grow(int n) {
        sceneKnown = Arrays.copyOf(sceneKnown, n);
        ballsKnown = Arrays.copyOf(ballsKnown, n);
        withScene = Arrays.copyOf(withScene, n);
        withBalls = Arrays.copyOf(withBalls, n);
        sceneAt = Arrays.copyOf(sceneAt, n);
        sceneCircle = Arrays.copyOf(sceneCircle, n);
        ballsAt = Arrays.copyOf(ballsAt, n);
        ballsCircle = Arrays.copyOf(ballsCircle, n);
        bySlot = Arrays.copyOf(bySlot, n);
        unknown = Arrays.copyOf(unknown, (n + 63) >>> 6);
        awakeSlots = Arrays.copyOf(awakeSlots, n);
        isAwake = Arrays.copyOf(isAwake, n);
        awakeIndex = Arrays.copyOf(awakeIndex, n);
        placeEarliest = Arrays.copyOf(placeEarliest, n);
        blockEarliest = Arrays.copyOf(blockEarliest, n / blockSize + 1);
        blockStale = Arrays.copyOf(blockStale, n / blockSize + 1);
        pointedAtBy = Arrays.copyOf(pointedAtBy, n);
        pointedAtCount = Arrays.copyOf(pointedAtCount, n);
        taken = Arrays.copyOf(taken, n);
    }

    /**
     * Files one more free ball (one an absorber let go of) in the next slot, where it is now, {@code elapsed} seconds
     * into the tick; it asks when the schedule next looks, and a collision sooner than what another ball knew becomes
     * that ball's too. Every other known collision stands.
     */
    void add(Ball ball, double elapsed) {
        if (filed == bySlot.length) {
            grow(2 * filed + 1);
        }
        int slot = filed++;
        bySlot[slot] = ball;
        ball.file(motions, slot);
        sceneKnown[slot] = false;
        ballsKnown[slot] = false;
        pointedAtCount[slot] = 0;
        taken[slot] = false;
        markUnknown(slot);
        fileSweep(ball, elapsed, true);
        awakeStale = true;
    }

    /**
     * The ball is somewhere its motion did not take it (an absorber took it and fired it, a portal moved it),
     * {@code elapsed} seconds into the tick: it is filed afresh in the next slot, as {@link #add} files a freed ball,
     * and its old slot, if it had one in this filing, is filed nowhere. What was to meet it must have been forgotten
     * ({@link #forget}) when it left; every other known collision stands.
     */
    void refile(Ball ball, double elapsed) {
        if (isFiled(ball)) {
            grid.remove(ball.slot());
        }
        add(ball, elapsed);
    }

    /** Which balls are awake changed (a wake-up, a capture, a new filing): found again before the next search. */
    void awakeChanged() {
        awakeStale = true;
    }

    /** A ball's velocity changed, {@code elapsed} seconds into the tick: its sweep is filed afresh from where it is. */
    void sped(Ball ball, double elapsed) {
        if (isFiled(ball)) {
            fileSweep(ball, elapsed, false);
        } else {
            fastest = Math.max(fastest, detector.speedOf(ball));
        }
    }

    /**
     * Files the filed ball's sweep from where it is, {@code elapsed} seconds into the tick, to the tick's end, with the
     * velocity it moves with ({@code first}: it takes its home cell there).
     */
    private void fileSweep(Ball ball, double elapsed, boolean first) {
        double vx = detector.motionX(ball);
        double vy = detector.motionY(ball);
        double speed = detector.speedOf(ball);
        fastest = Math.max(fastest, speed);
        double seconds = Math.max(0, until - elapsed);
        if (first) {
            grid.add(ball, vx, vy, speed, seconds);
        } else {
            grid.moves(ball, vx, vy, speed, seconds);
        }
    }

    /** Whether the ball is filed now (not held since before the last filing). */
    boolean isFiled(Ball ball) {
        int slot = ball.slot();
        return slot < filed && bySlot[slot] == ball;
    }

    /**
     * Whether the ball is filed but was taken out of play since (an absorber or a sink took it): the cell it was filed
     * in no longer bounds where it is, so freed again it must be filed afresh.
     */
    boolean wasTaken(Ball ball) {
        return isFiled(ball) && taken[ball.slot()];
    }

    /**
     * The earliest collision of the awake balls within the window, {@code elapsed} seconds into the tick. The balls
     * whose collisions are not known are asked first, in slot order (asking about a ball may tell a later one of a
     * sooner pair). Then the earliest known time is found from the blocks' earliest, and of the known collisions no
     * later than it by {@link Tolerances#TIME_TIE} (near-ties) the first circle in board order is taken, else the first
     * (each ball's with the scene before its with balls): a rule that does not depend on the order of the search, so
     * it reads only the blocks that hold a near-tie.
     */
    Collision next(List<Ball> awake, double elapsed, double window) {
        if (awakeStale) {
            findAwake(awake);
        }
        askTheUnknown(elapsed, window);
        int blocks = (awakeCount + blockSize - 1) / blockSize;
        double earliest = Double.POSITIVE_INFINITY;
        for (int block = 0; block < blocks; block++) {
            if (blockStale[block]) {
                int first = block * blockSize;
                blockEarliest[block] = earliestOf(first, Math.min(first + blockSize, awakeCount));
                blockStale[block] = false;
            }
            earliest = Math.min(earliest, blockEarliest[block]);
        }
        if (earliest == Double.POSITIVE_INFINITY) {
            return null;
        }
        best.reset(elapsed, window, earliest);
        for (int block = 0; block < blocks && !best.foundCircle(); block++) {
            if (!best.isNearTie(blockEarliest[block])) {
                continue;
            }
            for (int k = block * blockSize, end = Math.min(k + blockSize, awakeCount); k < end; k++) {
                if (best.isNearTie(placeEarliest[k])) {
                    int slot = awakeSlots[k];
                    best.offer(slot, true, sceneAt[slot], sceneCircle[slot]);
                    best.offer(slot, false, ballsAt[slot], ballsCircle[slot]);
                }
            }
        }
        Contact contact = best.withScene() ? withScene[best.slot()] : withBalls[best.slot()];
        return found.set(best.time(), bySlot[best.slot()], contact);
    }

    /** The earliest {@code at} of the known collisions of the awake balls in places [first, end). */
    private double earliestOf(int first, int end) {
        double earliest = Double.POSITIVE_INFINITY;
        for (int k = first; k < end; k++) {
            // a comparison, not Math.min: no time is NaN or -0.0 (Earliest drops NaN; elapsed + a time is +0.0 at least)
            if (placeEarliest[k] < earliest) {
                earliest = placeEarliest[k];
            }
        }
        return earliest;
    }

    /** A known collision of the slot changed: its block's earliest is found again before the next search. */
    private void changedAt(int slot) {
        if (isAwake[slot]) {
            int place = awakeIndex[slot];
            placeEarliest[place] = Math.min(sceneAt[slot], ballsAt[slot]);
            blockStale[place / blockSize] = true;
        }
    }

    private void findAwake(List<Ball> awake) {
        Arrays.fill(isAwake, false);
        awakeCount = 0;
        for (int i = 0; i < awake.size(); i++) {
            int slot = awake.get(i).slot();
            awakeIndex[slot] = awakeCount;
            placeEarliest[awakeCount] = Math.min(sceneAt[slot], ballsAt[slot]);
            awakeSlots[awakeCount++] = slot;
            isAwake[slot] = true;
        }
        Arrays.fill(blockStale, true);
        awakeStale = false;
    }

    /** Asks about every awake ball whose collisions are not known, in slot order; a sleeping one waits to wake. */
    private void askTheUnknown(double elapsed, double window) {
        for (int w = 0; w << 6 < filed; w++) {
            for (long bits = unknown[w]; bits != 0; bits &= bits - 1) {
                int slot = (w << 6) + Long.numberOfTrailingZeros(bits);
                if (!isAwake[slot]) {
                    continue;
                }
                Ball ball = bySlot[slot];
                if (!sceneKnown[slot]) {
                    knowWithScene(slot, elapsed, detector.againstScene(ball, window));
                }
                if (!ballsKnown[slot]) {
                    askAgainstBalls(ball, elapsed, window);
                }
                unknown[w] &= ~(1L << slot);
            }
        }
    }

    private void markUnknown(int slot) {
        unknown[slot >>> 6] |= 1L << slot;
    }

    /** Files the ball's earliest collision with the scene, found {@code elapsed} seconds into the tick. */
    private void knowWithScene(int slot, double elapsed, Earliest found) {
        Contact contact = found.contact();
        sceneKnown[slot] = true;
        withScene[slot] = contact;
        sceneAt[slot] = contact == null ? Double.POSITIVE_INFINITY : elapsed + found.time();
        sceneCircle[slot] = contact != null && found.isCircle();
        changedAt(slot);
    }

    /** The ball's velocity or position changed other than by moving on: ask again about it. */
    void forget(Ball ball) {
        if (!isFiled(ball)) {
            return;   // not filed now (held since before the last filing): nothing is known of it
        }
        int slot = ball.slot();
        taken[slot] |= ball.isCaptured();
        // A ball just captured or sunk is forgotten too: what was to meet it where it was must not meet it in the
        // absorber (a ball fired from an absorber, knocked back into it by the next ball, bounced that one off where
        // it had been).
        sceneKnown[slot] = false;
        ballsKnown[slot] = false;
        markUnknown(slot);
        int[] pointing = pointedAtBy[slot];
        for (int k = 0; k < pointedAtCount[slot]; k++) {
            int other = pointing[k];
            if (ballsKnown[other] && withBalls[other] != null && partner(withBalls[other]) == ball) {
                ballsKnown[other] = false;
                markUnknown(other);
            }
        }
        pointedAtCount[slot] = 0;
    }

    /**
     * Something in the box from (x0, y0) to (x1, y1) moves otherwise than it did: every filed ball that can reach the
     * box within {@code window} seconds asks again about the scene (its collisions with balls stand).
     */
    void forgetReaching(double x0, double y0, double x1, double y1, double window) {
        for (int slot = 0; slot < filed; slot++) {
            Ball ball = bySlot[slot];
            double reach = Arena.BALL_RADIUS + detector.speedOf(ball) * window
                    + Tolerances.REACH_MARGIN;
            if (ball.x() + reach >= x0 && ball.x() - reach <= x1 && ball.y() + reach >= y0 && ball.y() - reach <= y1) {
                sceneKnown[slot] = false;
                markUnknown(slot);
            }
        }
    }

    private void forgetAll() {
        Arrays.fill(sceneKnown, false);
        Arrays.fill(ballsKnown, false);
        Arrays.fill(pointedAtCount, 0);
        Arrays.fill(taken, false);
        Arrays.fill(unknown, 0);
        for (int slot = 0; slot < filed; slot++) {
            markUnknown(slot);
        }
    }

    private static Ball partner(Contact contact) {
        return ((Contact.OtherBall) contact).other();
    }

    /**
     * Files a ball's earliest known ball collision, found {@code elapsed} seconds into the tick: in {@code time}
     * seconds it meets {@code contact} (null: none), noted with its partner.
     */
    private void knowWithBalls(int slot, double elapsed, Contact contact, double time, boolean circle) {
        ballsKnown[slot] = true;
        withBalls[slot] = contact;
        ballsAt[slot] = contact == null ? Double.POSITIVE_INFINITY : elapsed + time;
        ballsCircle[slot] = contact != null && circle;
        changedAt(slot);
        if (contact == null) {
            return;
        }
        int partner = partner(contact).slot();
        int[] pointing = pointedAtBy[partner];
        if (pointing == null || pointing.length == pointedAtCount[partner]) {
            int grown = Math.max(4, 2 * pointedAtCount[partner]);
            pointing = pointing == null ? new int[grown] : Arrays.copyOf(pointing, grown);
            pointedAtBy[partner] = pointing;
        }
        pointing[pointedAtCount[partner]++] = slot;
    }

    /**
     * Into {@code into}, in slot order (the board's, but for balls filed since the filing), every filed ball whose
     * centre lies now, {@code elapsed} seconds into the tick, within {@code within} of the ball's along x and along y,
     * the ball itself too: a question of the cells around it, where asking every ball on the board cost a cluster of
     * 32 balls 6,400 tests at 200 balls.
     */
    void filedNear(Ball ball, double within, double elapsed, List<Ball> into) {
        into.clear();
        double near = within + Tolerances.REACH_MARGIN;
        int found = grid.near(ball.x(), ball.y(), near, within);
        for (int i = 0; i < found; i++) {
            into.add(bySlot[grid.found(i)]);   // in slot order
        }
    }

    /**
     * The ball against every ball it can reach in the window; a pair sooner than what the other ball knew becomes
     * the other's too. A sleeping ball is a still target; it never asks.
     */
    private void askAgainstBalls(Ball ball, double elapsed, double window) {
        Earliest earliest = againstBalls;
        earliest.reset(window);
        double speed = detector.speedOf(ball);
        // No ball farther now than this can meet this one within the window (the pair test's own bound, wider).
        double near = 2 * Arena.BALL_RADIUS + (speed + fastest) * window + Tolerances.REACH_MARGIN;
        // The same bound for each ball found, with its own speed and twice the margin: rounding never passes a pair.
        double alone = 2 * Arena.BALL_RADIUS + speed * window + 2 * Tolerances.REACH_MARGIN;
        // The pair test's first bounds, on the slots' centres and motions (the pair's as the detector takes them, where
        // no ball has finished): most pairs found are refused there, by the grid, without reading either ball.
        boolean bySlots = detector.noneFinished();
        int nearby = grid.nearSweep(ball, detector.motionX(ball), detector.motionY(ball), window, near, alone, bySlots);
        int mine = ball.slot();
        for (int i = 0; i < nearby; i++) {
            int theirs = grid.found(i);
            if (theirs == mine || bySlot[theirs].isCaptured()) {
                continue;
            }
            Ball other = bySlot[theirs];
            pair.reset(window);
            detector.againstBall(other, ball, window, pair);
            Contact found = pair.contact();
            if (found == null) {
                continue;
            }
            earliest.offer(pair.time(), ball, other.asContact(), true);
            if (ballsKnown[theirs] && (withBalls[theirs] == null || elapsed + pair.time() < ballsAt[theirs])) {
                knowWithBalls(theirs, elapsed, found, pair.time(), true);
            }
        }
        knowWithBalls(mine, elapsed, earliest.contact(), earliest.time(), earliest.isCircle());
    }

}
