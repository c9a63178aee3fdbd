package gizmoball.bench;

import gizmoball.model.Board;
import physics.Vect;

import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;

/**
 * A benchmark scene: how to build its board, how long to simulate it, the keys pressed along the way,
 * and, where the mathematics gives one, the exact ball positions at any time. Scenes without an exact
 * path are compared against {@link Method#REFERENCE}.
 */
public record Scene(String name, double duration, Supplier<Board> board, KeyScript keys, Optional<ExactPath> exact,
                    Optional<Double> exactApexY) {

    /** Exact ball centres (in the board's ball order) at simulated time t. */
    @FunctionalInterface
    public interface ExactPath {
        List<Vect> at(double t);
    }

    long ticks(Method m) {
        return Math.round(duration * m.ticksPerSecond());
    }
}
