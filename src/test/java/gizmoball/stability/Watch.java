package gizmoball.stability;

import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.LoopModes;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.LoopMode;

import java.time.Duration;
import java.util.List;
import java.util.function.BiConsumer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

/**
 * Ticks a board and checks after every tick what must always hold: the model's invariants (finite state,
 * inside the board, no penetration beyond 1e-6 L, speed limit), our own position checks (finite, centre
 * and whole ball inside the walls), and no energy above the start value plus an allowance. A failure names
 * the case, the tick and what went wrong.
 * <p>
 * The energy check applies to the game's CONTINUOUS loop only. The SEED loop resolves at most one
 * collision per tick, so balls resting together keep the gravity of the ticks in which another ball's
 * contact was resolved instead of theirs, and gain energy by design; the benchmark measures how much.
 */
final class Watch {

    /** Relative rounding allowance on energy; beyond it, energy must not rise unless allowed below. */
    static final double NO_GAIN = 1e-9;

    /** Liveness only: a loop stuck in endless zero-time collisions never returns from tick(). */
    private static final Duration FREEZE = Duration.ofSeconds(60);

    private final String name;
    private final Board board;
    private final double dt;
    private double energyAllowance;

    Watch(String name, Board board, double dt) {
        this.name = name;
        this.board = board;
        this.dt = dt;
    }

    /**
     * With gravity the loop's step (velocity first, then a straight move) may end a tick with a little more
     * energy than it began after a bounce inside the tick: at most about one tick of fall at the top speed.
     */
    Watch allowEnergyGainOfOneTickAt(double speed) {
        energyAllowance = 2 * Math.abs(board.gravity()) * speed * dt;
        return this;
    }

    /** Flippers or absorbers add energy here: no energy check. */
    Watch energyMayGrow() {
        energyAllowance = Double.POSITIVE_INFINITY;
        return this;
    }

    Watch run(int ticks) {
        return run(ticks, (tick, b) -> { });
    }

    /** Runs the ticks; {@code afterTick} may add checks or act on the board (keys) between ticks. */
    Watch run(int ticks, BiConsumer<Integer, Board> afterTick) {
        double e0 = board.energy();
        assertTimeoutPreemptively(FREEZE, () -> {
            for (int tick = 1; tick <= ticks; tick++) {
                board.tick(dt);
                String where = name + ", tick " + tick + " of " + ticks + " (dt " + dt + ", " + LoopModes.of(board) + ")";
                List<String> violations = Invariants.violations(board);
                assertThat(violations).as(where + ": model invariants").isEmpty();
                for (BallView ball : board.balls()) {
                    assertInside(where, ball);
                }
                if (LoopModes.of(board) == LoopMode.CONTINUOUS) {
                    assertThat(board.energy()).as(where + ": energy (start " + e0 + ")").isLessThanOrEqualTo(
                            e0 + NO_GAIN * Math.max(1, Math.abs(e0)) + energyAllowance);
                }
                afterTick.accept(tick, board);
            }
        }, () -> name + ": tick() did not return within " + FREEZE.toSeconds() + " s");
        return this;
    }

    private static void assertInside(String where, BallView ball) {
        double x = ball.position().x();
        double y = ball.position().y();
        assertThat(Double.isFinite(x) && Double.isFinite(y)
                && Double.isFinite(ball.velocity().x()) && Double.isFinite(ball.velocity().y()))
                .as(where + ": ball " + ball.name() + " finite, at " + ball.position() + " moving " + ball.velocity())
                .isTrue();
        double r = ball.radius();
        double slack = 1e-6;
        assertThat(x).as(where + ": ball " + ball.name() + " x inside the walls").isBetween(r - slack, Board.SIZE - r + slack);
        assertThat(y).as(where + ": ball " + ball.name() + " y inside the walls").isBetween(r - slack, Board.SIZE - r + slack);
    }

    Board board() {
        return board;
    }
}
