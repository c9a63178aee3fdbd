package gizmoball.model.loop;

/** The earliest collision found by stage 3: in {@code time} seconds, {@code ball} touches {@code contact}. */
record Collision(double time, Ball ball, Contact contact) {
}
