package gizmoball.preview;

import java.util.List;
import java.util.Optional;
import physics.Vect;

/**
 * Where one ball goes, as the model plays a copy of the board: its position after each tick (index 0 is
 * where it starts), the centre positions at which it hit something, and the first trigger it sets off.
 *
 * @param path       one point per tick, {@code ticks + 1} in all
 * @param collisions the ball's centre at each of its collisions, in order
 * @param trigger    the first gizmo (or the outer walls) the ball hit that drives others, with their names
 * @param seconds    simulated seconds covered: less than asked for when the time budget ran out first
 */
public record Prediction(String ball, List<Point> path, List<Vect> collisions, Optional<Trigger> trigger,
                         double seconds, boolean shortened) {
    public Prediction {
        path = List.copyOf(path);
        collisions = List.copyOf(collisions);
    }

    /**
     * A point of the path; {@code free}: the ball flew here from the previous point (false while an absorber
     * holds it, and after a tick in which it was captured, even if the absorber fired it again at once).
     */
    public record Point(Vect at, boolean free) {
    }

    /** The ball hit {@code source} at {@code at}, which triggers {@code targets}. */
    public record Trigger(String source, Vect at, List<String> targets) {
        public Trigger {
            targets = List.copyOf(targets);
        }
    }

    public int ticks() {
        return path.size() - 1;
    }
}
