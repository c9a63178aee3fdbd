package gizmoball.model.loop;

/**
 * The earliest collision found by stage 3: in {@code time} seconds, {@code ball} touches {@code contact}. The schedule
 * keeps one and sets it afresh at each search, as a physics engine's step reuses its contact records: the loop reads
 * it, resolving the collision, before it searches again, and a tick of 200 collisions makes none.
 */
final class Collision {
    private double time;
    private Ball ball;
    private Contact contact;

    /** Becomes the collision found: returns itself. */
    Collision set(double newTime, Ball newBall, Contact newContact) {
        time = newTime;
        ball = newBall;
        contact = newContact;
        return this;
    }

    double time() {
        return time;
    }

    Ball ball() {
        return ball;
    }

    Contact contact() {
        return contact;
    }

    /** The ball it meets, when it meets one; else null (a surface). */
    Ball otherBall() {
        return contact instanceof Contact.OtherBall other ? other.other() : null;
    }

    @Override
    public String toString() {
        return ball + " meets " + contact + " in " + time + " s";
    }
}
