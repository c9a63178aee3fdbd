package gizmoball.controller;

import gizmoball.model.Board;
import gizmoball.replay.KeyScript;
import gizmoball.replay.ScriptedPlay;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.DoubleConsumer;
import java.util.function.LongSupplier;
import javax.swing.Timer;

/**
 * Runs the simulation: a Swing Timer ticks the board on the event dispatch thread, the same thread that
 * paints it, so a view never sees a board half-way through a tick. The timer fires about twice per
 * tick and the {@link TickPacer} decides how many ticks each event runs, keeping simulated time in step
 * with real time (scaled by the {@link Speed}) without the drift of one tick per (late or early) timer event.
 * Every tick is {@code tickSeconds} long at any speed: a slower speed ticks less often. The timer and the clock
 * are handed in (the game's are a Swing Timer and System.nanoTime), so tests drive both by hand.
 *
 * <p>While it {@linkplain #watch watches} a replay, each tick first presses the replay's keys due then, as the
 * headless runner does, so the window shows the very game that was recorded, at any speed; it stops at the replay's
 * last tick.
 */
public final class GameLoop {
    private static final int MAX_CATCH_UP_TICKS = 4;

    private final Board board;
    private final double tick;
    private final Pulse timer;
    private final LongSupplier clock;
    private final List<Runnable> runningListeners = new ArrayList<>();
    private final List<DoubleConsumer> frameListeners = new ArrayList<>();
    private Consumer<RuntimeException> failureHandler = e -> {
        throw e;
    };
    private Speed speed = Speed.NORMAL;
    private TickPacer pacer;
    private long lastEventNanos;
    private boolean resumeOnRelease;
    /** The replay being watched, or null. */
    private Watching watching;

    /** A replay played to its last tick; {@code ended} is told when it gets there. */
    private record Watching(ScriptedPlay play, long lastTick, Runnable ended) {
    }

    /**
     * Sends the loop an event every {@code periodMillis} on the event dispatch thread while it is started: the
     * game's is a coalescing Swing Timer ({@link #swingTimer}).
     */
    interface Pulse {
        void start();

        void stop();

        boolean isRunning();
    }

    /** Makes the loop's pulse, given its period and what each event runs. */
    @FunctionalInterface
    interface PulseSource {
        Pulse every(int periodMillis, Runnable event);
    }

    public GameLoop(Board board, double tickSeconds) {
        this(board, tickSeconds, GameLoop::swingTimer, System::nanoTime);
    }

    /** With another pulse and another clock in nanoseconds (the tests drive both). */
    GameLoop(Board board, double tickSeconds, PulseSource pulses, LongSupplier clock) {
        this.board = board;
        this.tick = tickSeconds;
        this.clock = clock;
        this.timer = pulses.every(Math.max(1, (int) (tickSeconds * 1000 / 2)), this::onTimer);
        pacer = pacerFor(speed);
    }

    /** A Swing Timer: its events come on the event dispatch thread, late ones coalesced into one. */
    private static Pulse swingTimer(int periodMillis, Runnable event) {
        Timer timer = new Timer(periodMillis, e -> event.run());
        timer.setCoalesce(true);
        return new Pulse() {
            @Override
            public void start() {
                timer.start();
            }

            @Override
            public void stop() {
                timer.stop();
            }

            @Override
            public boolean isRunning() {
                return timer.isRunning();
            }
        };
    }

    public boolean isRunning() {
        return timer.isRunning();
    }

    public void start() {
        if (!timer.isRunning()) {
            pacer = pacerFor(speed);
            lastEventNanos = clock.getAsLong();
            timer.start();
            fireRunningChanged();
        }
    }

    public void stop() {
        resumeOnRelease = false;
        if (timer.isRunning()) {
            timer.stop();
            fireRunningChanged();
        }
        fireFrame(1);
    }

    /**
     * Pauses a running game until {@link #release()} (while a modal dialog is open, say). A {@link #stop()} in
     * between, such as loading another board, means it stays stopped.
     */
    public void hold() {
        if (timer.isRunning()) {
            timer.stop();
            resumeOnRelease = true;
            fireRunningChanged();
            fireFrame(1);
        }
    }

    /** Resumes a game paused by {@link #hold()}, unless it was stopped meanwhile. */
    public void release() {
        if (resumeOnRelease) {
            resumeOnRelease = false;
            start();
        }
    }

    public Speed speed() {
        return speed;
    }

    /** Takes effect at once, also while running (the part of a tick already waited for is forgotten). */
    public void setSpeed(Speed s) {
        speed = s;
        pacer = pacerFor(s);
    }

    /** One tick, for stepping while stopped. */
    public void step() {
        ticks(1);
    }

    /**
     * From now on the board plays {@code replay}'s keys at their ticks (the board must be the replay's board as built,
     * at tick 0) until its last tick, where the loop stops and tells {@code ended}. The loop keeps its speed and
     * running state; {@link #stopWatching()} or a new watch ends it.
     */
    public void watch(KeyScript keys, long lastTick, Runnable ended) {
        watching = new Watching(new ScriptedPlay(board, keys, tick), lastTick, ended);
    }

    /** Ticks go back to the player's keys alone. */
    public void stopWatching() {
        watching = null;
    }

    public boolean isWatching() {
        return watching != null;
    }

    /** Told when a tick throws; the loop has stopped by then, rather than failing again 60 times a second. */
    public void setFailureHandler(Consumer<RuntimeException> handler) {
        failureHandler = handler;
    }

    public void addRunningListener(Runnable l) {
        runningListeners.add(l);
    }

    /**
     * Told, after each timer event that ran a tick, and at every event while slower than 1x (when ticks are
     * further apart than frames), how far real time has come from the last tick towards the next (0..1), and 1
     * when the game stops: what a view needs to draw between ticks. The ticks themselves do not change.
     */
    public void addFrameListener(DoubleConsumer l) {
        frameListeners.add(l);
    }

    private void onTimer() {
        long now = clock.getAsLong();
        elapsed(now - lastEventNanos);
        lastEventNanos = now;
    }

    /** Runs the ticks owed after {@code nanos} of real time (what each timer event does; tests call it directly). */
    void elapsed(long nanos) {
        int due = pacer.ticksFor(nanos);
        ticks(due);
        if (due > 0 || speed.factor() < 1) {
            fireFrame(pacer.fractionOfNextTick());
        }
    }

    private TickPacer pacerFor(Speed s) {
        return new TickPacer(tick / s.factor(), MAX_CATCH_UP_TICKS);
    }

    private void ticks(int n) {
        try {
            for (int i = 0; i < n; i++) {
                if (watching == null) {
                    board.tick(tick);
                } else if (board.ticks() < watching.lastTick()) {
                    watching.play().tick();
                }
                if (watching != null && board.ticks() >= watching.lastTick()) {
                    Runnable ended = watching.ended();
                    watching = null;
                    stop();
                    ended.run();
                    return;
                }
            }
        } catch (RuntimeException e) {
            stop();
            failureHandler.accept(e);
        }
    }

    private void fireFrame(double fraction) {
        frameListeners.forEach(l -> l.accept(fraction));
    }

    private void fireRunningChanged() {
        runningListeners.forEach(Runnable::run);
    }
}
