package gizmoball.model.loop;

/**
 * How often each last-resort guard of the loop fired (docs/design.md, "Guards"). None fires in ordinary play: each
 * count above zero is a case the contact handling did not resolve on its own.
 *
 * @param wedged       a ball with more zero-time collisions in one tick than any real contact needs was stopped
 * @param pinched      a ball squeezed out between a flipper and what it came back from, more often in one tick
 *                     than any real squeeze needs, was stopped with the flipper (a jam, where no squeeze can get
 *                     the ball out, is physics: {@link PlayEvent.Jammed})
 * @param collisionCap a tick with more collisions than its balls can need ended early
 */
public record GuardCounts(long wedged, long pinched, long collisionCap) {
    public static final GuardCounts NONE = new GuardCounts(0, 0, 0);

    public GuardCounts plus(GuardCounts other) {
        if (other.total() == 0) {
            return this;   // a value: nothing added is this one (a tick fires none, and is added to the total)
        }
        return new GuardCounts(wedged + other.wedged, pinched + other.pinched, collisionCap + other.collisionCap);
    }

    public long total() {
        return wedged + pinched + collisionCap;
    }
}
