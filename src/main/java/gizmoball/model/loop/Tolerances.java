package gizmoball.model.loop;

/**
 * Every length and speed tolerance of the model and the board files, in one place, so that what the loop leaves
 * behind is always what the editor and the loader accept (docs/design.md, "Tolerances").
 *
 * <p>They nest: {@link #CONTACT} &lt; {@link #PLACEMENT} &lt; {@link #INVARIANT}. The loop never leaves a ball
 * deeper than {@code CONTACT} in a surface (a persistent contact whose ball drifts in by more is pushed back out to
 * touching); the editor and the loader refuse only overlaps deeper than {@code PLACEMENT}, ten times that, so a
 * board saved at any moment of play loads again; the invariants the tests check allow {@code INVARIANT}, a
 * thousand times more, so that a test failure means a real penetration, never rounding.
 */
public final class Tolerances {
    /** L: a ball this close to touching a surface is touching it (persistent contacts are kept within this). */
    public static final double CONTACT = 1e-9;
    /** L: overlaps up to this depth are touching for placements and for the loader, and for a contact cluster. */
    public static final double PLACEMENT = 1e-8;
    /** L: the invariants allow this depth of penetration (rounding of many collisions, never a real overlap). */
    public static final double INVARIANT = 1e-6;
    /**
     * L/s: a normal speed this small is rounding, not motion. A touch that closes no faster is a graze, not a
     * collision; a ball approaching a surface no faster comes to rest on it even without gravity.
     */
    public static final double ROUNDING_SPEED = 1e-9;

    /**
     * Radians: a ball passing a circle (a corner, a bumper, a ball) this close to tangent grazes it. Rounding of a
     * path that just touches a corner reports its contact up to about 1e-7 of a turn early, closing at a speed that
     * is rounding too; ignoring such a touch lets the ball overlap the circle by at most (R + r) angle^2 / 2, below
     * 1e-12 L. Faces have no such allowance: along a face a graze could sink a ball.
     */
    public static final double GRAZE_ANGLE = 1e-6;

    private Tolerances() {
    }
}
