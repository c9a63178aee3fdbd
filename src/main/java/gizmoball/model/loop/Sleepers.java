package gizmoball.model.loop;

import java.util.ArrayDeque;
import java.util.Collection;
import java.util.Deque;

/**
 * Wakes sleeping balls (docs/design.md, "Sleeping"). A ball that wakes may have been the support of others asleep
 * on it, so waking spreads along persistent contacts: nothing is left asleep on a ball that may move away.
 */
public final class Sleepers {
    private final Collection<Ball> balls;

    /**
     * Over a live view of the board's balls, which it reads at each wake-up. For the board, not for views.
     */
    public Sleepers(Collection<Ball> balls) {
        this.balls = balls;
    }

    /** Wakes the ball and every sleeping ball that rests on it, directly or through others. */
    void wake(Ball ball) {
        Deque<Ball> woken = new ArrayDeque<>();
        if (ball.isAsleep()) {
            ball.wake();
        }
        woken.add(ball);
        while (!woken.isEmpty()) {
            // one reference per support, not one per sleeping ball it is looked for among
            ContactRef onSupport = new ContactRef.OnBall(woken.poll().name());
            for (Ball other : balls) {
                if (other.isAsleep() && other.contacts().contains(onSupport)) {
                    other.wake();
                    woken.add(other);
                }
            }
        }
    }

    /**
     * Wakes every free ball whose disc meets the box (and, through them, what rests on them). For the board, not for
     * views.
     */
    public void wakeWithin(double minX, double minY, double maxX, double maxY) {
        double r = Arena.BALL_RADIUS + Tolerances.CONTACT;
        for (Ball ball : balls) {
            if (ball.isAsleep() && within(ball, r, minX, minY, maxX, maxY)) {
                wake(ball);
            }
        }
    }

    /**
     * The box (a cell that turned solid or nothing) changed under every ball whose disc comes within a radius of
     * it, far more than any contact it holds there lies apart: each forgets its contacts and wakes, and so does what
     * rests on it. The board beyond did not change, and its balls keep their contacts and their sleep (a gate or a drop
     * target switching every tick left no pile anywhere on the board at rest: fuzz seed 1000596). For the board, not
     * for views.
     */
    public void disturbNear(double minX, double minY, double maxX, double maxY) {
        double r = 2 * Arena.BALL_RADIUS;
        for (Ball ball : balls) {
            if (within(ball, r, minX, minY, maxX, maxY)) {
                ball.disturb();
                wake(ball);
            }
        }
    }

    /** Whether the ball's centre lies within {@code r} of the box along x and along y. */
    private static boolean within(Ball ball, double r, double minX, double minY, double maxX, double maxY) {
        double x = ball.x();
        double y = ball.y();
        return x + r >= minX && x - r <= maxX && y + r >= minY && y - r <= maxY;
    }

    /**
     * The board changed under every ball: each forgets its contacts and wakes. For the board, not for views.
     */
    public void disturbAll() {
        balls.forEach(Ball::disturb);
    }
}
