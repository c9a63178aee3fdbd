package gizmoball.preview;

import gizmoball.model.Board;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.Struck;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.LongSupplier;
import physics.Vect;

/**
 * The aim preview's prediction: the real model ticks a copy of the board, with every collision and trigger
 * as in play and no key pressed (so flippers stay at rest), and the ball's positions are read after each
 * tick. The board given is never changed.
 * <p>
 * The prediction must keep up with the mouse, so it runs in slices of a budget of real time: a slice stops
 * before a tick that would overrun it, with a shorter horizon, instead of holding up the event thread. A
 * later slice carries on from there.
 */
public final class Predictor {
    /** How far ahead the preview looks. */
    public static final double HORIZON_SECONDS = 3;
    /** Real time one slice of prediction may take: half a 60 Hz frame. */
    public static final long BUDGET_NANOS = 8_000_000;

    private final LongSupplier clock;

    /** {@code clock} gives nanoseconds (System::nanoTime; tests pass their own). */
    public Predictor(LongSupplier clock) {
        this.clock = clock;
    }

    public Predictor() {
        this(System::nanoTime);
    }

    /** The path of {@code ball} over {@code seconds} of ticks of {@code dt}, as far as {@code budgetNanos} allows. */
    public Prediction predict(Board board, String ball, double seconds, double dt, long budgetNanos) {
        return start(board, ball, seconds, dt).advance(budgetNanos);
    }

    /** A prediction to be made in slices: nothing is ticked before the first {@link Run#advance}. */
    public Run start(Board board, String ball, double seconds, double dt) {
        return new Run(board.copy(), ball, (int) Math.round(seconds / dt), dt);
    }

    /** One prediction in progress, on its own copy of the board. */
    public final class Run {
        private final Board copy;
        private final String ball;
        private final int ticks;
        private final double dt;
        private final List<Prediction.Point> path = new ArrayList<>();
        private final List<Vect> collisions = new ArrayList<>();
        private Optional<Prediction.Trigger> trigger = Optional.empty();
        /** A sink took the ball: nothing more to predict. */
        private boolean sunk;

        private Run(Board copy, String ball, int ticks, double dt) {
            this.copy = copy;
            this.ball = ball;
            this.ticks = ticks;
            this.dt = dt;
            path.add(point(copy.ball(ball).orElseThrow(() -> new IllegalArgumentException("no ball named " + ball))));
        }

        public boolean isDone() {
            return sunk || path.size() > ticks;
        }

        /**
         * Ticks on for at most {@code budgetNanos} (at least one tick, so that every slice makes progress) and
         * returns the prediction so far, {@link Prediction#shortened()} until it covers the whole horizon.
         */
        public Prediction advance(long budgetNanos) {
            long start = clock.getAsLong();
            for (int done = 0; !isDone(); done++) {
                long used = clock.getAsLong() - start;
                // Stop before a tick that would overrun the budget, judging a tick by the average so far.
                if (done > 0 && used + used / done > budgetNanos) {
                    break;
                }
                copy.tick(dt);
                boolean captured = false;
                for (PlayEvent event : copy.lastTick().events()) {
                    captured |= hitBy(event);
                }
                Optional<BallView> b = copy.ball(ball);
                if (b.isEmpty()) {
                    sunk = true;   // a sink took it: its path ends where it went in
                    path.add(new Prediction.Point(collisions.get(collisions.size() - 1), false));
                    break;
                }
                path.add(new Prediction.Point(b.get().position(), !b.get().isCaptured() && !captured));
            }
            return new Prediction(ball, path, collisions, trigger, (path.size() - 1) * dt, !isDone());
        }

        /**
         * A hit or capture of the predicted ball: a dot, and the first one that drives other gizmos is the trigger.
         * Returns whether it was a capture.
         */
        private boolean hitBy(PlayEvent event) {
            Struck struck;
            Vect at;
            if (event instanceof PlayEvent.Hit hit && ball.equals(hit.ball())) {
                struck = hit.struck();
                at = hit.at();
            } else if (event instanceof PlayEvent.Captured captured && ball.equals(captured.ball())) {
                struck = TriggerSource.gizmo(captured.absorber());
                at = captured.at();
            } else if (event instanceof PlayEvent.Sunk sunkBy && ball.equals(sunkBy.ball())) {
                struck = TriggerSource.gizmo(sunkBy.sink());
                at = sunkBy.at();
            } else if (event instanceof PlayEvent.Teleported through && ball.equals(through.ball())) {
                struck = TriggerSource.gizmo(through.portal());
                at = through.at();
            } else {
                return false;
            }
            collisions.add(at);
            if (trigger.isEmpty() && struck instanceof TriggerSource source) {
                List<String> targets = copy.connections().stream().filter(c -> c.source().equals(source))
                        .map(Connection::target).toList();
                if (!targets.isEmpty()) {
                    trigger = Optional.of(new Prediction.Trigger(source.name(), at, targets));
                }
            }
            return event instanceof PlayEvent.Captured || event instanceof PlayEvent.Sunk
                    || event instanceof PlayEvent.Teleported;   // no line from the mouth to the pair's
        }

        private static Prediction.Point point(BallView b) {
            return new Prediction.Point(b.position(), !b.isCaptured());
        }
    }
}
