package gizmoball.controller;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.Map;
import java.util.Set;

/**
 * Turns the raw key events of the platform into one down per physical press and one up per physical
 * release, so that holding a key does not toggle a flipper back and forth.
 * <p>
 * Platforms auto-repeat a held key in two ways: repeated presses without releases (Windows, macOS), and
 * release+press pairs arriving together (X11). The first is dropped because the key is already down.
 * For the second, a release is held back for {@code pairWindowMillis} after it arrived: a press of the
 * same key in that window cancels it (auto-repeat; no person releases and presses a key again that fast),
 * otherwise {@link #flush} delivers it. Times are the arrival times in milliseconds of any steady clock.
 */
public final class KeyRepeatFilter {
    /** Receives the filtered edges. */
    public interface Edges {
        void down(int keyCode);

        void up(int keyCode);
    }

    private final Edges edges;
    private final long pairWindowMillis;
    private final Set<Integer> held = new HashSet<>();
    private final Map<Integer, Long> pendingReleases = new HashMap<>();

    public KeyRepeatFilter(Edges edges, long pairWindowMillis) {
        this.edges = edges;
        this.pairWindowMillis = pairWindowMillis;
    }

    public void pressed(int keyCode) {
        if (pendingReleases.remove(keyCode) == null && held.add(keyCode)) {
            edges.down(keyCode);
        }
    }

    /** A release of a key that this filter never saw go down (e.g. pressed before the window had focus) is ignored. */
    public void released(int keyCode, long arrivedMillis) {
        if (held.contains(keyCode)) {
            pendingReleases.put(keyCode, arrivedMillis);
        }
    }

    /** Delivers the releases that arrived at least the pair window before {@code nowMillis} and were not cancelled. */
    public void flush(long nowMillis) {
        for (Iterator<Map.Entry<Integer, Long>> it = pendingReleases.entrySet().iterator(); it.hasNext(); ) {
            Map.Entry<Integer, Long> pending = it.next();
            if (nowMillis - pending.getValue() >= pairWindowMillis) {
                it.remove();
                up(pending.getKey());
            }
        }
    }

    /** Releases every held key now, e.g. when the window loses focus and would never see the real releases. */
    public void releaseAll() {
        pendingReleases.clear();
        for (Integer keyCode : Set.copyOf(held)) {
            up(keyCode);
        }
    }

    public boolean hasPendingReleases() {
        return !pendingReleases.isEmpty();
    }

    private void up(int keyCode) {
        held.remove(keyCode);
        edges.up(keyCode);
    }
}
