package gizmoball.model.loop;

import java.util.Arrays;

/**
 * The broad phase for ball pairs: free balls filed by the cell their centre was in when filed, each cell with the
 * highest speed of its balls since. Positions go stale as balls move on within a tick, so a query widens its radius
 * by how far any ball can have moved since, and passes over a cell whose balls are too slow to come within reach:
 * balls far apart are never asked about each other, and a fast ball does not make every query read the cells of
 * slow ones (docs/design.md, "Detection asks only about what can be reached").
 *
 * <p>Its books are flat arrays kept from filing to filing and grown when the balls outgrow them: each cell's balls are
 * a chain of slots (first, next), so a query reads ints for the empty cells of its box and touches only the balls it
 * may find, and a filing costs one link per ball, never a list per cell.
 */
public final class BallGrid {
    private static final int CELLS = Arena.SIZE * Arena.SIZE;
    private static final int NONE = -1;
    /** By cell: the slot of the first and of the last ball filed there ({@link #NONE}: empty). */
    private final int[] first = new int[CELLS];
    private final int[] last = new int[CELLS];
    /** By cell: the highest speed (L/s) of a ball filed there, since it was filed. */
    private final double[] cellFastest = new double[CELLS];
    /** By row: the highest speed (L/s) of a ball filed in the row since it was filed, the most of its cells'. */
    private final double[] rowFastest = new double[Arena.SIZE];
    /** The cells holding a ball, so that clearing costs the balls filed, not the 400 cells. */
    private final int[] filled = new int[CELLS];
    private int filledCount;
    /** By slot ({@link Ball#slot()}): the ball, the next slot filed in its cell ({@link #NONE}: none), its cell. */
    private Ball[] bySlot = new Ball[0];
    private int[] next = new int[0];
    private int[] cellOfSlot = new int[0];
    /**
     * By slot: the centre where the ball was filed, and its highest speed since: a ball farther from a query than
     * that speed can have closed since is passed over without reading the ball (a read of each ball the cells give
     * was most of a query's time at 200 balls).
     */
    private double[] filedX = new double[0];
    private double[] filedY = new double[0];
    private double[] slotFastest = new double[0];
    /** What the last {@link #near} found, in its order: {@link #found(int)} for i below its count. */
    private Ball[] found = new Ball[0];

    /** Empty; the loop files the balls at each tick. The board keeps one for its loop, not for views. */
    public BallGrid() {
        Arrays.fill(first, NONE);
    }

    /** Empty, ready for {@code balls} balls in slots 0 to balls - 1. */
    void clear(int balls) {
        for (int k = 0; k < filledCount; k++) {
            first[filled[k]] = NONE;
            cellFastest[filled[k]] = 0;
        }
        filledCount = 0;
        Arrays.fill(rowFastest, 0);
        room(balls);
    }

    /** Books for slots 0 to {@code balls} - 1, what is filed kept. */
    private void room(int balls) {
        if (bySlot.length < balls) {
            int size = Math.max(balls, 2 * bySlot.length);
            bySlot = Arrays.copyOf(bySlot, size);
            next = Arrays.copyOf(next, size);
            cellOfSlot = Arrays.copyOf(cellOfSlot, size);
            filedX = Arrays.copyOf(filedX, size);
            filedY = Arrays.copyOf(filedY, size);
            slotFastest = Arrays.copyOf(slotFastest, size);
            found = new Ball[size];
        }
    }

    /** Files the ball, in its slot, where it is now, moving at {@code speed} (L/s): after the balls filed before it. */
    void add(Ball ball, double speed) {
        double x = ball.x();
        double y = ball.y();
        int index = index(cell(x), cell(y));
        int slot = ball.slot();
        room(slot + 1);
        filedX[slot] = x;
        filedY[slot] = y;
        slotFastest[slot] = 0;
        if (first[index] == NONE) {
            filled[filledCount++] = index;
            first[index] = slot;
        } else {
            next[last[index]] = slot;
        }
        last[index] = slot;
        next[slot] = NONE;
        bySlot[slot] = ball;
        cellOfSlot[slot] = index;
        sped(ball, speed);
    }

    /**
     * The ball in {@code slot} is filed there no more (it went elsewhere than it could move to, and is filed again in
     * another slot): its place in its cell's chain stays, filed at no place, so the test on where a ball was filed
     * passes it over in every query.
     */
    void remove(int slot) {
        filedX[slot] = Double.POSITIVE_INFINITY;
        filedY[slot] = Double.POSITIVE_INFINITY;
    }

    /** The filed ball moves at {@code speed} (L/s) now: its cell's balls may go farther. */
    void sped(Ball ball, double speed) {
        int slot = ball.slot();
        slotFastest[slot] = Math.max(slotFastest[slot], speed);
        int index = cellOfSlot[slot];
        cellFastest[index] = Math.max(cellFastest[index], speed);
        rowFastest[index / Arena.SIZE] = Math.max(rowFastest[index / Arena.SIZE], speed);
    }

    /**
     * Finds every filed ball whose centre lies now within the square of half-side {@code near} around (x, y) (or of
     * {@code alone} + f {@code window}, f the ball's own fastest since filing, where that is less), looked
     * for among the balls filed within {@code reach} of it ({@code reach} covers how far any ball moved since it was
     * filed), in the order of their cells, row by row, and of their filing in a cell; returns how many
     * ({@link #found(int)} reads them). The test on where a ball is now keeps out the balls that filed cells bring in
     * but that lie too far for any pair test to accept: in a pile of 100 balls, three in four of those the cells give.
     *
     * <p>A cell is passed over when none of its balls can be within reach of a ball at (x, y) moving at s: they are
     * no faster than the cell's fastest f, so they are now within f {@code stale} of the cell, and a pair farther
     * apart than {@code alone} + f {@code window} (alone: 2 r + s window and a margin) cannot meet in the window.
     * That is the pair test's own bound (the two balls' relative speed is at most s + f), so no pair that could meet
     * is passed over, and the balls found come in the same order. A row's fastest bounds its cells' the same way: a
     * row out of that reach is passed over whole, and of the others only the columns within it (and one more each
     * side, past any rounding) are read, so one fast ball widens only its own row's search, not every row's.
     */
    int near(double x, double y, double reach, double near, double alone, double window, double stale) {
        int count = 0;
        int x0 = cell(x - reach);
        int x1 = cell(x + reach);
        int y0 = cell(y - reach);
        int y1 = cell(y + reach);
        for (int cy = y0; cy <= y1; cy++) {
            double dy = Math.max(0, Math.max(cy - y, y - (cy + 1)));
            double rowWithin = alone + rowFastest[cy] * window + rowFastest[cy] * stale;
            if (dy > rowWithin) {
                continue;
            }
            int from = Math.max(x0, cell(x - rowWithin) - 1);
            int to = Math.min(x1, cell(x + rowWithin) + 1);
            for (int cx = from, index = index(from, cy); cx <= to; cx++, index++) {
                int slot = first[index];
                if (slot == NONE) {
                    continue;
                }
                double fastest = cellFastest[index];
                double within = alone + fastest * window + fastest * stale;
                if (dy > within || Math.max(0, Math.max(cx - x, x - (cx + 1))) > within) {
                    continue;
                }
                for (; slot != NONE; slot = next[slot]) {
                    // The pair test's bound for this ball, no faster than its fastest since filing, if tighter.
                    double ballNear = Math.min(near, alone + slotFastest[slot] * window);
                    double moved = slotFastest[slot] * stale + Tolerances.REACH_MARGIN;
                    if (Math.abs(filedX[slot] - x) > ballNear + moved || Math.abs(filedY[slot] - y) > ballNear + moved) {
                        continue;   // it cannot have come within reach since it was filed
                    }
                    Ball ball = bySlot[slot];
                    if (Math.abs(ball.x() - x) <= ballNear && Math.abs(ball.y() - y) <= ballNear) {
                        found[count++] = ball;
                    }
                }
            }
        }
        return count;
    }

    /** The {@code i}th ball the last {@link #near} found. */
    Ball found(int i) {
        return found[i];
    }

    private static int index(int cx, int cy) {
        return cy * Arena.SIZE + cx;
    }

    private static int cell(double coordinate) {
        return (int) Math.max(0, Math.min(Arena.SIZE - 1, Math.floor(coordinate)));
    }
}
