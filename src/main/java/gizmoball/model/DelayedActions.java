package gizmoball.model;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.GizmoBase;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Actions ordered with a delay (docs/design.md, "The wiring kit"), in the order given: each is performed at the first
 * tick boundary its due time has reached, on the board's clock, by the gizmo of its name if the board still has one.
 */
final class DelayedActions {
    private final Registry registry;
    private final List<Delayed> delayed = new ArrayList<>();

    /**
     * An action the gizmo named {@code gizmo} performs at the first tick boundary at or after board time {@code due}.
     */
    private record Delayed(double due, String gizmo, Action action) {
        /**
         * How far short of the due time a tick may end and still count as reaching it: the clock is a sum of ticks,
         * and 30 ticks of 1/60 s add up to a hair less than 0.5 s.
         */
        static final double ROUNDING = 1e-9;

        boolean isDue(double now) {
            return due <= now + ROUNDING;
        }
    }

    DelayedActions(Registry registry) {
        this.registry = registry;
    }

    void add(double due, GizmoBase gizmo, Action action) {
        delayed.add(new Delayed(due, gizmo.name(), action));
    }

    /**
     * A tick starts at {@code now}: the actions due by then are performed through {@code play}, earliest first (those
     * due together in the order they were given).
     */
    void performDue(double now, Play play) {
        if (delayed.isEmpty()) {
            return;   // most ticks: a stream over nothing still cost a tick a twentieth of its time
        }
        if (!anyDue(now)) {
            return;   // most ticks of a board with actions waiting
        }
        List<Delayed> due = delayed.stream().filter(d -> d.isDue(now))
                .sorted(Comparator.comparingDouble(Delayed::due)).toList();
        delayed.removeIf(d -> d.isDue(now));
        for (Delayed d : due) {
            GizmoBase gizmo = registry.gizmo(d.gizmo());
            if (gizmo != null) {
                play.perform(gizmo, d.action(), now);
            }
        }
    }

    private boolean anyDue(double now) {
        for (int i = 0; i < delayed.size(); i++) {
            if (delayed.get(i).isDue(now)) {
                return true;
            }
        }
        return false;
    }

    /** The delayed actions of {@code source} become these (a copy of a board in play). */
    void copyFrom(DelayedActions source) {
        delayed.clear();
        delayed.addAll(source.delayed);
    }

    void clear() {
        delayed.clear();
    }
}
