package gizmoball.model;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.Struck;
import gizmoball.model.loop.TickEvents;

import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * The events of play (for sound, flashes, the game): those since the last tick's end, and the last tick's, which are
 * read in place until the next tick ends. Two sets of columns take turns, so that play makes no list of its events.
 */
final class EventLog {
    private EventColumns pending = new EventColumns();
    private EventColumns lastTick = new EventColumns();

    void record(PlayEvent event) {
        pending.add(event);
    }

    /** {@code ball} hit {@code struck}, as {@link PlayEvent.Hit} has it: its centre is where it is now. */
    void recordHit(Ball ball, Struck struck, GizmoKind kind, double speed) {
        pending.addHit(ball.name(), ball.x(), ball.y(), struck, kind, speed);
    }

    /** A tick ends: the events since the last one's end are its events, and the next tick's start anew. */
    TickEvents closeTick() {
        EventColumns closed = pending;
        pending = lastTick;
        pending.clear();
        lastTick = closed;
        return closed;
    }

    /**
     * Events in the order they happened, a hit's parts in columns, as Box2D keeps its contact events: a board of
     * 100 balls hears some 20 hits a tick, and a record each was most of what its tick allocated (issue 39). The
     * columns grow to the busiest tick and are reused.
     */
    private static final class EventColumns implements TickEvents {
        private static final int FIRST_CAPACITY = 16;
        private int size;
        /** The event itself where it is no hit; null where it is one, its parts in the columns below. */
        private PlayEvent[] others = new PlayEvent[FIRST_CAPACITY];
        private Struck[] struck = new Struck[FIRST_CAPACITY];
        private GizmoKind[] kinds = new GizmoKind[FIRST_CAPACITY];
        private double[] speeds = new double[FIRST_CAPACITY];
        private String[] balls = new String[FIRST_CAPACITY];
        private double[] xs = new double[FIRST_CAPACITY];
        private double[] ys = new double[FIRST_CAPACITY];

        void add(PlayEvent event) {
            int i = next();
            others[i] = event;
        }

        /** A hit of the ball {@code ball}, whose centre is at (x, y) now, as {@link PlayEvent.Hit} has it. */
        void addHit(String ball, double x, double y, Struck what, GizmoKind kind, double speed) {
            int i = next();
            struck[i] = what;
            kinds[i] = kind;
            speeds[i] = speed;
            balls[i] = ball;
            xs[i] = x;
            ys[i] = y;
        }

        void clear() {
            Arrays.fill(others, 0, size, null);
            size = 0;
        }

        private int next() {
            if (size == others.length) {
                int capacity = 2 * size;
                others = Arrays.copyOf(others, capacity);
                struck = Arrays.copyOf(struck, capacity);
                kinds = Arrays.copyOf(kinds, capacity);
                speeds = Arrays.copyOf(speeds, capacity);
                balls = Arrays.copyOf(balls, capacity);
                xs = Arrays.copyOf(xs, capacity);
                ys = Arrays.copyOf(ys, capacity);
            }
            return size++;
        }

        @Override
        public int size() {
            return size;
        }

        @Override
        public boolean isHit(int i) {
            return others[checked(i)] == null;
        }

        @Override
        public Struck struck(int i) {
            return struck[hit(i)];
        }

        @Override
        public GizmoKind kind(int i) {
            return kinds[hit(i)];
        }

        @Override
        public double speed(int i) {
            return speeds[hit(i)];
        }

        @Override
        public PlayEvent event(int i) {
            PlayEvent other = others[checked(i)];
            return other != null ? other : new PlayEvent.Hit(struck[i], kinds[i], speeds[i], balls[i], xs[i], ys[i]);
        }

        @Override
        public List<PlayEvent> copy() {
            PlayEvent[] events = new PlayEvent[size];
            for (int i = 0; i < size; i++) {
                events[i] = event(i);
            }
            return List.of(events);
        }

        private int checked(int i) {
            return Objects.checkIndex(i, size);
        }

        private int hit(int i) {
            if (!isHit(i)) {
                throw new IllegalArgumentException("event " + i + " is no hit: " + others[i]);
            }
            return i;
        }
    }
}
