package gizmoball.model.loop;

import java.util.Arrays;

/**
 * The broad phase for ball pairs: each free ball is filed in every cell that meets its swept box, the box its centre
 * sweeps from now to the tick's end, widened by its radius and {@link Tolerances#SWEPT_SLACK}. Two balls that touch at
 * some moment of the tick both lie within a radius of the point midway between their centres, so the cell of that
 * point holds both: a question about a ball reads only the cells its own box meets, however fast other balls fly
 * (a grid that filed each ball in one cell had to read every cell a fast ball could come from: 56 cells a question on
 * {@code slow-200-balls.txt}). See docs/design.md, "Detection asks only about what can be reached".
 *
 * <p>A ball whose velocity changes is filed again from where it is: it leaves the cells its new box does not meet and
 * enters those it did not (mostly none: a slow ball's box stays in the same cells). The balls a question finds come
 * in the order of the cell each was first filed in (its home: the cell of its centre then), row by row, and then of
 * their slots: the order of offers, which settles near-ties, does not depend on how the boxes fall.
 *
 * <p>Its books are flat arrays kept from tick to tick and grown when the balls or a cell's entries outgrow them, so a
 * tick in the steady state allocates nothing here.
 */
public final class BallGrid {
    private static final int CELLS = Arena.SIZE * Arena.SIZE;
    private static final int NONE = -1;
    /** L: half the side of a still ball's box beyond its centre. */
    private static final double HALF = Arena.BALL_RADIUS + Tolerances.SWEPT_SLACK;
    /** By cell: the slots filed there, and how many. */
    private final int[][] entrySlots = new int[CELLS][];
    private final int[] entryCount = new int[CELLS];
    /**
     * By slot ({@link Ball#slot()}; which ball holds a slot is the schedule's to know): its home cell, and the columns
     * and rows of the cells it is filed in, from first to last ({@link #NONE}: filed nowhere).
     */
    private int[] homeOfSlot = new int[0];
    private int[] fromColumn = new int[0];
    private int[] toColumn = new int[0];
    private int[] fromRow = new int[0];
    private int[] toRow = new int[0];
    /** The filed balls' centres, by slot (read there, not through each ball: a question reads no ball's object). */
    private Motions centres = new Motions();
    /** By slot: its speed (L/s) as last filed, for the pair test's bound. */
    private double[] speedOfSlot = new double[0];
    /** By slot: the question that last found it, so that a ball in several of a question's cells is found once. */
    private long[] seenBy = new long[0];
    private long questions;
    /** The slots the last question found, in its order: {@link #found(int)} for i below its count. */
    private int[] found = new int[0];
    /** The columns and rows of the cells the last {@link #sweep} met, from first to last. */
    private int sweptFromColumn;
    private int sweptToColumn;
    private int sweptFromRow;
    private int sweptToRow;

    /** Empty; the loop files the balls at each tick. The board keeps one for its loop, not for views. */
    public BallGrid() {
        for (int cell = 0; cell < CELLS; cell++) {
            entrySlots[cell] = new int[4];
        }
    }

    /** Empty, ready for {@code balls} balls in slots 0 to balls - 1, whose centres {@code filed} keeps. */
    void clear(int balls, Motions filed) {
        Arrays.fill(entryCount, 0);
        centres = filed;
        room(balls);
    }

    /** Books for slots 0 to {@code balls} - 1, what is filed kept. */
    private void room(int balls) {
        if (homeOfSlot.length < balls) {
            int size = Math.max(balls, 2 * homeOfSlot.length);
            homeOfSlot = Arrays.copyOf(homeOfSlot, size);
            fromColumn = Arrays.copyOf(fromColumn, size);
            toColumn = Arrays.copyOf(toColumn, size);
            fromRow = Arrays.copyOf(fromRow, size);
            toRow = Arrays.copyOf(toRow, size);
            speedOfSlot = Arrays.copyOf(speedOfSlot, size);
            seenBy = Arrays.copyOf(seenBy, size);
            found = new int[size];
        }
    }

    /**
     * Files the ball, in its slot, where it is now, its home the cell of its centre, moving at (vx, vy) (L/s), its
     * speed {@code speed}, for the {@code seconds} left in the tick.
     */
    void add(Ball ball, double vx, double vy, double speed, double seconds) {
        int slot = ball.slot();
        room(slot + 1);
        homeOfSlot[slot] = index(Arena.cellOf(ball.x()), Arena.cellOf(ball.y()));
        seenBy[slot] = 0;
        fromColumn[slot] = NONE;
        moves(ball, vx, vy, speed, seconds);
    }

    /**
     * The filed ball moves from where it is now at (vx, vy) (L/s), its speed {@code speed}, for the {@code seconds}
     * left in the tick: it is filed in the cells of that sweep, and in no other. Its home stays.
     */
    void moves(Ball ball, double vx, double vy, double speed, double seconds) {
        int slot = ball.slot();
        speedOfSlot[slot] = speed;
        sweep(ball, vx, vy, seconds);
        int x0 = sweptFromColumn;
        int x1 = sweptToColumn;
        int y0 = sweptFromRow;
        int y1 = sweptToRow;
        int oldX0 = fromColumn[slot];
        int oldX1 = toColumn[slot];
        int oldY0 = fromRow[slot];
        int oldY1 = toRow[slot];
        if (oldX0 == x0 && oldX1 == x1 && oldY0 == y0 && oldY1 == y1) {
            return;
        }
        for (int cy = oldY0; oldX0 != NONE && cy <= oldY1; cy++) {
            for (int cx = oldX0; cx <= oldX1; cx++) {
                if (cx < x0 || cx > x1 || cy < y0 || cy > y1) {
                    leave(index(cx, cy), slot);
                }
            }
        }
        for (int cy = y0; cy <= y1; cy++) {
            for (int cx = x0; cx <= x1; cx++) {
                if (oldX0 == NONE || cx < oldX0 || cx > oldX1 || cy < oldY0 || cy > oldY1) {
                    enter(index(cx, cy), slot);
                }
            }
        }
        fromColumn[slot] = x0;
        toColumn[slot] = x1;
        fromRow[slot] = y0;
        toRow[slot] = y1;
    }

    private void enter(int index, int slot) {
        int count = entryCount[index];
        if (count == entrySlots[index].length) {
            entrySlots[index] = Arrays.copyOf(entrySlots[index], 2 * count);
        }
        entrySlots[index][count] = slot;
        entryCount[index] = count + 1;
    }

    /** Takes the slot out of the cell, the cell's last entry taking its place (the order in a cell is no one's). */
    private void leave(int index, int slot) {
        int[] slots = entrySlots[index];
        int last = entryCount[index] - 1;
        for (int k = 0; k <= last; k++) {
            if (slots[k] == slot) {
                slots[k] = slots[last];
                entryCount[index] = last;
                return;
            }
        }
    }

    /**
     * The ball in {@code slot} is filed there no more (it went elsewhere than it could move to, and is filed again in
     * another slot): it leaves its cells.
     */
    void remove(int slot) {
        for (int cy = fromRow[slot]; fromColumn[slot] != NONE && cy <= toRow[slot]; cy++) {
            for (int cx = fromColumn[slot]; cx <= toColumn[slot]; cx++) {
                leave(index(cx, cy), slot);
            }
        }
        fromColumn[slot] = NONE;
    }

    /**
     * The balls that the ball, at (vx, vy) (L/s) for {@code seconds}, can touch within them are filed in the cells of
     * its own swept box: finds those filed there whose centre now lies within {@code within} of its along x and along
     * y, and within {@code alone} + s {@code seconds} too, s each one's speed as filed. With {@code byMotions}, only
     * those that may meet it within {@code seconds} by the slots' centres and motions ({@link Approach#mayMeetBall},
     * the pair test's first bound), itself left out; else the ball itself among them. Returns how many
     * ({@link #found(int)} reads them), in the order of their homes, row by row, and of their slots: the few a bound
     * keeps are sorted, not the many it refuses.
     */
    int nearSweep(Ball ball, double vx, double vy, double seconds, double within, double alone, boolean byMotions) {
        sweep(ball, vx, vy, seconds);
        int count = find(sweptFromColumn, sweptToColumn, sweptFromRow, sweptToRow, ball.x(), ball.y(), within, alone,
                seconds, byMotions ? ball.slot() : NONE);
        for (int i = 1; i < count; i++) {   // by insertion: a question finds a few
            int slot = found[i];
            long key = order(slot);
            int k = i;
            for (; k > 0 && order(found[k - 1]) > key; k--) {
                found[k] = found[k - 1];
            }
            found[k] = slot;
        }
        return count;
    }

    /**
     * Finds every filed ball whose centre now lies within {@code within} of (x, y) along x and along y, looked for in
     * the cells within {@code reach} (at least {@code within}) of it; returns how many, in slot order (the board's,
     * but for balls filed since the filing).
     */
    int near(double x, double y, double reach, double within) {
        int count = find(Arena.cellOf(x - reach), Arena.cellOf(x + reach), Arena.cellOf(y - reach),
                Arena.cellOf(y + reach), x, y, within, within, 0, NONE);
        Arrays.sort(found, 0, count);
        return count;
    }

    /** The columns and rows of the cells that meet the ball's swept box, into the swept fields. */
    private void sweep(Ball ball, double vx, double vy, double seconds) {
        double x = ball.x();
        double y = ball.y();
        double toX = x + vx * seconds;
        double toY = y + vy * seconds;
        sweptFromColumn = Arena.cellOf(Math.min(x, toX) - HALF);
        sweptToColumn = Arena.cellOf(Math.max(x, toX) + HALF);
        sweptFromRow = Arena.cellOf(Math.min(y, toY) - HALF);
        sweptToRow = Arena.cellOf(Math.max(y, toY) + HALF);
    }

    /**
     * The balls filed in columns cx0 to cx1 of rows cy0 to cy1 whose centre lies within the smaller of {@code within}
     * and {@code alone} + s {@code window} of (x, y) along x and along y, s each one's speed as filed, and, unless
     * {@code meeting} is {@link #NONE}, that may meet the ball in slot {@code meeting} within {@code window} by their
     * slots' motions, that ball left out; each once, in the order the cells give them.
     */
    private int find(int cx0, int cx1, int cy0, int cy1, double x, double y, double within, double alone,
                     double window, int meeting) {
        long question = ++questions;
        int count = 0;
        double[] xs = centres.x;
        double[] ys = centres.y;
        for (int cy = cy0; cy <= cy1; cy++) {
            for (int cx = cx0, index = index(cx0, cy); cx <= cx1; cx++, index++) {
                int[] slots = entrySlots[index];
                for (int k = 0, n = entryCount[index]; k < n; k++) {
                    int slot = slots[k];
                    if (seenBy[slot] == question) {
                        continue;   // found in another cell
                    }
                    seenBy[slot] = question;
                    // The pair test's bound for this ball, if tighter (its own speed, not the fastest ball's).
                    double ballNear = Math.min(within, alone + speedOfSlot[slot] * window);
                    if (Math.abs(xs[slot] - x) <= ballNear && Math.abs(ys[slot] - y) <= ballNear
                            && (meeting == NONE || slot != meeting && mayMeet(slot, meeting, window))) {
                        found[count++] = slot;
                    }
                }
            }
        }
        return count;
    }

    /** {@link Approach#mayMeetBall} for the balls filed in two slots, the first's centre and motion less the second's. */
    private boolean mayMeet(int first, int second, double window) {
        Motions m = centres;
        return Approach.mayMeetBall(m.x[first] - m.x[second], m.y[first] - m.y[second], m.vx[first] - m.vx[second],
                m.vy[first] - m.vy[second], window);
    }

    private long order(int slot) {
        return (long) homeOfSlot[slot] << 32 | slot;
    }

    /** The slot of the {@code i}th ball the last question found. */
    int found(int i) {
        return found[i];
    }

    private static int index(int cx, int cy) {
        return cy * Arena.SIZE + cx;
    }
}
