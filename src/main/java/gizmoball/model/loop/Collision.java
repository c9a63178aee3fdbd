package gizmoball.model.loop;

import java.util.List;

/** The earliest collision found by stage 3: in {@code time} seconds, {@code ball} touches {@code contact}. */
record Collision(double time, Ball ball, Contact contact) {
    /** The ball it meets, when it meets one; else null (a surface). */
    Ball otherBall() {
        return contact instanceof Contact.OtherBall other ? other.other() : null;
    }

    /** The balls it moves: its ball, and the ball that ball meets. */
    List<Ball> balls() {
        Ball other = otherBall();
        return other == null ? List.of(ball) : List.of(ball, other);
    }
}
