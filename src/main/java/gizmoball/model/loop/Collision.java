package gizmoball.model.loop;

/** The earliest collision found by stage 3: in {@code time} seconds, {@code ball} touches {@code contact}. */
record Collision(double time, Ball ball, Contact contact) {
    /** The ball it meets, when it meets one; else null (a surface). */
    Ball otherBall() {
        return contact instanceof Contact.OtherBall other ? other.other() : null;
    }
}
