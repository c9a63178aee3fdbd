package gizmoball.model.loop;

import gizmoball.model.gizmo.GizmoKind;

import java.util.List;

/**
 * The events of the last tick, read in place until the next tick ends (docs/design.md, "What a tick allocates"). The
 * board's own listeners (drop targets, the game) read them so every tick, and a crowd's score of hits makes no record
 * each; {@link TickReport#events()} is the copy to keep.
 */
public interface TickEvents {
    int size();

    /** Whether event {@code i} is a {@link PlayEvent.Hit}: {@link #struck}, {@link #kind} and {@link #speed} read it. */
    boolean isHit(int i);

    /** What the hit {@code i} struck. */
    Struck struck(int i);

    /** The kind of gizmo the hit {@code i} struck; null for the outer walls and another ball. */
    GizmoKind kind(int i);

    /** The speed in L/s at which the hit {@code i} closed. */
    double speed(int i);

    /** Event {@code i}, made anew if it is a hit. */
    PlayEvent event(int i);

    /** Every event, in order, in a list of its own. */
    List<PlayEvent> copy();
}
