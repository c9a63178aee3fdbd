package gizmoball.view;

import java.util.ArrayDeque;

/** Frames per second over the last second, from the time stamps (System.nanoTime) of painted frames. */
public final class FpsMeter {
    private static final long WINDOW_NANOS = 1_000_000_000L;
    private final ArrayDeque<Long> frames = new ArrayDeque<>();

    public void frame(long nanos) {
        frames.addLast(nanos);
        forgetBefore(nanos - WINDOW_NANOS);
    }

    /** Frames painted in the second before {@code nanos}. */
    public int fps(long nanos) {
        forgetBefore(nanos - WINDOW_NANOS);
        return frames.size();
    }

    private void forgetBefore(long start) {
        while (!frames.isEmpty() && frames.peekFirst() <= start) {
            frames.removeFirst();
        }
    }
}
