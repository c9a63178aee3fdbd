package gizmoball.model.loop;

import java.util.Arrays;

/**
 * The centres of the balls filed in a tick and the velocities they move with, side by side by slot
 * ({@link Ball#slot()}). Stage 2 moves every awake ball to each collision: at 200 balls some 16,000 moves a tick, and
 * one pass over four arrays costs a fraction of a pass that visits each ball's object. While filed, a ball reads and
 * writes its centre here ({@link Ball#file}, {@link Ball#unfile}); the tick's last act gives each its centre back.
 *
 * <p>A slot's velocity is the ball's while it moves (awake and free) and zero while it rests, so a pass moves exactly
 * the balls stage 2 moved one by one, with the same doubles: a resting ball's {@code x + 0 dt + 0.0} is x. A slot its
 * ball left (filed again elsewhere) moves on unread.
 */
final class Motions {
    double[] x = new double[0];
    double[] y = new double[0];
    double[] vx = new double[0];
    double[] vy = new double[0];
    /** Slots 0 to {@code used} - 1 are filed in this tick. */
    private int used;

    /** No slot is filed (a tick starts). */
    void clear() {
        used = 0;
    }

    /** Whether any ball is filed in this tick: stage 2 then moves the slots, not the balls. */
    boolean isUsed() {
        return used > 0;
    }

    /** Room for slot {@code slot}, which is filed now. */
    void use(int slot) {
        if (slot >= x.length) {
            int size = Math.max(slot + 1, 2 * x.length);
            x = Arrays.copyOf(x, size);
            y = Arrays.copyOf(y, size);
            vx = Arrays.copyOf(vx, size);
            vy = Arrays.copyOf(vy, size);
        }
        used = Math.max(used, slot + 1);
    }

    /** Every filed ball straight on for {@code dt} seconds, as {@link Ball#advance} moves one. */
    void advance(double dt) {
        for (int i = 0; i < used; i++) {
            x[i] = x[i] + vx[i] * dt + 0.0;
            y[i] = y[i] + vy[i] * dt + 0.0;
        }
    }
}
