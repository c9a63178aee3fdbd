package gizmoball.model.loop;

import java.util.ArrayList;
import java.util.List;

/**
 * The balls that move no more in this tick (SEED, and a ball over its own collision cap), asked about for every pair
 * and every move: each ball carries its mark, so asking costs a field read however many are finished.
 */
final class FinishedBalls {
    private final List<Ball> marked = new ArrayList<>();

    void add(Ball ball) {
        if (!ball.finished) {
            ball.finished = true;
            marked.add(ball);
        }
    }

    /** The collision's ball, and the ball it meets. */
    void addBallsOf(Collision collision) {
        add(collision.ball());
        if (collision.otherBall() != null) {
            add(collision.otherBall());
        }
    }

    /** It moves on after all (a moving shape carries it). */
    void remove(Ball ball) {
        if (ball.finished) {
            ball.finished = false;
            marked.remove(ball);
        }
    }

    boolean contains(Ball ball) {
        return ball.finished;
    }

    boolean isEmpty() {
        return marked.isEmpty();
    }

    /** A tick begins: none is finished. */
    void clear() {
        for (int i = 0; i < marked.size(); i++) {
            marked.get(i).finished = false;
        }
        marked.clear();
    }
}
