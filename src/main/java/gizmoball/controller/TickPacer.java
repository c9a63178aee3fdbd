package gizmoball.controller;

/**
 * Decides how many model ticks a timer event runs so that simulated time follows real time. Late
 * events catch up, but by at most {@code maxTicksPerEvent}; anything beyond is dropped, so a long
 * stall (a dialog, a GC pause, a slow machine) slows the game down instead of freezing the window
 * while it replays seconds of simulation.
 */
public final class TickPacer {
    private final long tickNanos;
    private final int maxTicksPerEvent;
    private long owedNanos;

    public TickPacer(double tickSeconds, int maxTicksPerEvent) {
        this.tickNanos = Math.round(tickSeconds * 1e9);
        this.maxTicksPerEvent = maxTicksPerEvent;
    }

    /** How much of the next tick real time has already brought, 0 (just ticked) to almost 1. */
    public double fractionOfNextTick() {
        return (double) owedNanos / tickNanos;
    }

    /** Ticks to run now, {@code elapsedNanos} of real time after the previous call. */
    public int ticksFor(long elapsedNanos) {
        owedNanos += Math.max(0, elapsedNanos);
        int ticks = (int) Math.min(maxTicksPerEvent, owedNanos / tickNanos);
        // Below the cap this keeps the part of a tick still owed; at the cap it also drops the excess.
        owedNanos = Math.min(owedNanos - ticks * tickNanos, tickNanos - 1);
        return ticks;
    }
}
