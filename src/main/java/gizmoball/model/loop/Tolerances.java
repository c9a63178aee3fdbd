package gizmoball.model.loop;

/**
 * Every tolerance of the model and the board files, in one place: lengths, speeds, times and rounding scales, so
 * that what the loop leaves behind is always what the editor and the loader accept (docs/design.md, "Tolerances").
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
    /** L: a persistent contact's penetration below this is rounding and left alone; deeper, the ball is put back. */
    static final double SNAP_DEPTH = CONTACT / 10;
    /** L: the margin around a ball's swept box when asking for what it can reach (touching shapes must be found). */
    static final double REACH_MARGIN = 1e-6;
    /**
     * L: how far beyond its radius a ball's swept box in the ball grid reaches: far above the rounding of a centre moved
     * step by step along its velocity, and above a snap onto a surface (at most {@link #CONTACT}).
     */
    static final double SWEPT_SLACK = 1e-3;
    /** s: collisions this close in time are simultaneous (the earliest search then prefers a circle). */
    static final double TIME_TIE = 1e-12;
    /**
     * L/s: a velocity component below this is rounding debris. Far below anything meaningful (resting-contact
     * projections leave components near 1e-14 that decide whether a ball is still closing on a corner), far above the
     * range where a collision time gap / speed overflows.
     */
    static final double NEGLIGIBLE_SPEED = 1e-100;

    // Rounding on a relative scale: each a multiple of the quantities it compares, far below any real change.
    /** Of the cluster's summed |v|^2: a change this small is rounding, not a loss or a gain. */
    static final double KEPT_ENERGY = 1e-12;
    /**
     * Of the set's scale: a pivot this small counts as zero, the row depending on the set (a face and the corner flush
     * with it, both touched along one normal).
     */
    static final double DEPENDENT_PIVOT = 1e-12;
    /** Of a unit direction: a correction along a ball's contacts may close on one by no more than this. */
    static final double TANGENT_ROUNDING = 1e-12;

    private Tolerances() {
    }
}
