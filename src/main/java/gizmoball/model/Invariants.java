package gizmoball.model;

import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.Tolerances;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Set;

import physics.Vect;

/**
 * The physical invariants of a board, for tests and the benchmark: no NaN or infinite ball state, every free ball
 * inside the board, no free ball inside a gizmo or another free ball by more than {@link Tolerances#INVARIANT} L, speeds
 * within {@link Board#MAX_SPEED}. Captured balls sit inside their absorber by design: only finiteness is checked.
 */
public final class Invariants {

    private Invariants() {
    }

    /** Empty when all hold; otherwise one line per violation, naming the ball and what is wrong. */
    public static List<String> violations(Board board) {
        return violations(board, Set.of());
    }

    /**
     * As {@link #violations(Board)}, except that the pairs in {@code passingThrough} (each the set of the two
     * balls' names) may overlap: balls placed on each other by a board file pass through each other until they
     * separate, and the caller, who saw them separate, takes the pair out from then on.
     */
    public static List<String> violations(Board board, Collection<Set<String>> passingThrough) {
        List<String> found = new ArrayList<>();
        List<Ball> free = new ArrayList<>();
        for (Ball ball : board.ballStates()) {
            Vect p = ball.position();
            Vect v = ball.velocity();
            if (!Double.isFinite(p.x()) || !Double.isFinite(p.y()) || !Double.isFinite(v.x()) || !Double.isFinite(v.y())) {
                found.add(ball + ": not a finite state");
                continue;
            }
            if (v.length() > Arena.MAX_SPEED * (1 + 1e-12)) {
                found.add(ball + ": speed " + v.length() + " over " + Arena.MAX_SPEED);
            }
            if (!ball.isCaptured()) {
                free.add(ball);
            }
        }
        double r = Arena.BALL_RADIUS;
        for (Ball ball : free) {
            Vect p = ball.position();
            if (p.x() < r - Tolerances.INVARIANT || p.x() > Arena.SIZE - r + Tolerances.INVARIANT
                    || p.y() < r - Tolerances.INVARIANT || p.y() > Arena.SIZE - r + Tolerances.INVARIANT) {
                found.add(ball + ": outside the board");
            }
            for (GizmoBase gizmo : board.gizmoBases()) {
                if (!nearFootprint(gizmo, p, r)) {
                    continue;   // every body lies within its footprint: a ball this far cannot be inside it
                }
                double depth = r - gizmo.signedDistance(p);
                if (depth > Tolerances.INVARIANT) {
                    found.add(ball + ": " + depth + " L inside " + gizmo);
                }
            }
        }
        for (int i = 0; i < free.size(); i++) {
            for (int j = i + 1; j < free.size(); j++) {
                double depth = 2 * r - Math.sqrt(free.get(i).position().distanceSquared(free.get(j).position()));
                if (depth > Tolerances.INVARIANT
                        && !passingThrough.contains(Set.of(free.get(i).name(), free.get(j).name()))) {
                    found.add(free.get(i) + ": " + depth + " L inside " + free.get(j));
                }
            }
        }
        return found;
    }

    private static boolean nearFootprint(GizmoBase gizmo, Vect p, double r) {
        return p.x() > gizmo.x() - r && p.x() < gizmo.x() + gizmo.width() + r
                && p.y() > gizmo.y() - r && p.y() < gizmo.y() + gizmo.height() + r;
    }
}
