package gizmoball.model;

import gizmoball.model.loop.PlayEvent;

import java.util.ArrayList;
import java.util.List;

/** The events of play (for sound and flashes) since the last tick's report, kept until the report takes them. */
final class EventLog {
    private final List<PlayEvent> pending = new ArrayList<>();

    void record(PlayEvent event) {
        pending.add(event);
    }

    /** The events since the last tick's report, for this tick's. */
    List<PlayEvent> drain() {
        if (pending.isEmpty()) {
            return List.of();   // most ticks: no copy of nothing
        }
        List<PlayEvent> events = List.copyOf(pending);
        pending.clear();
        return events;
    }
}
