package gizmoball.model.loop;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;

import physics.Vect;

/**
 * A ball caught between a swinging flipper and the surfaces it has just come back from (docs/design.md, "Pinched
 * balls"). Left to bounce, it would go back and forth ever faster in a gap the flipper keeps closing, without end.
 * Those bounces tend to a velocity that leaves all the surfaces at once; this class finds the one nearest to the
 * velocity the ball has. Each surface is a constraint on the ball's velocity v, with its unit normal n pointing into
 * the ball and the speed s at which the surface itself moves along n: {@code v . n >= s}. The half-planes of
 * velocities may have nothing in common (surfaces that face each other squarely, or a pocket the flipper closes);
 * a ball that could escape only faster than {@link Arena#MAX_SPEED} cannot escape at all: it jams the flipper.
 */
final class Squeeze {
    /** One surface: the ball must move at least at {@code speed} along the unit {@code normal}. */
    record Side(Vect normal, double speed) {
        boolean allows(Vect velocity) {
            return velocity.dot(normal) >= speed - Tolerances.ROUNDING_SPEED;
        }

        /** The nearest velocity to {@code velocity} on the edge of this side's half-plane. */
        Vect onEdge(Vect velocity) {
            return velocity.plus(normal.times(speed - velocity.dot(normal)));
        }
    }

    private Squeeze() {
    }

    /**
     * The velocity nearest to {@code velocity} that leaves every side, or empty when the ball is jammed: no velocity
     * within {@link Arena#MAX_SPEED} leaves them all.
     */
    static Optional<Vect> leaving(Vect velocity, List<Side> sides) {
        Optional<Vect> slowest = nearestLeaving(Vect.ZERO, sides);
        if (slowest.isEmpty() || slowest.get().length() > Arena.MAX_SPEED) {
            return Optional.empty();
        }
        return nearestLeaving(velocity, sides);
    }

    /**
     * The velocity every side allows nearest to {@code from}. The allowed velocities are an intersection of
     * half-planes, a convex set in the plane, so its point nearest to another lies on at most two edges: it is
     * {@code from} itself, or its projection onto one edge, or a corner where two edges meet.
     */
    private static Optional<Vect> nearestLeaving(Vect from, List<Side> sides) {
        if (allowedByAll(from, sides)) {
            return Optional.of(from);
        }
        List<Vect> candidates = new ArrayList<>();
        for (Side side : sides) {
            candidates.add(side.onEdge(from));
        }
        Optional<Vect> onOneEdge = nearestAllowed(from, candidates, sides);
        if (onOneEdge.isPresent()) {
            return onOneEdge;
        }
        candidates.clear();
        for (int i = 0; i < sides.size(); i++) {
            for (int j = i + 1; j < sides.size(); j++) {
                corner(sides.get(i), sides.get(j)).ifPresent(candidates::add);
            }
        }
        return nearestAllowed(from, candidates, sides);
    }

    private static Optional<Vect> nearestAllowed(Vect from, List<Vect> candidates, List<Side> sides) {
        return candidates.stream().filter(candidate -> allowedByAll(candidate, sides))
                .min(Comparator.comparingDouble(candidate -> candidate.minus(from).length()));
    }

    private static boolean allowedByAll(Vect velocity, List<Side> sides) {
        return sides.stream().allMatch(side -> side.allows(velocity));
    }

    /**
     * Where both edges meet: v . a = a.speed and v . b = b.speed. None when they are parallel: then, if the sides
     * allow anything at all, a projection onto one edge already lies in what they allow.
     */
    private static Optional<Vect> corner(Side a, Side b) {
        Vect p = a.normal();
        Vect q = b.normal();
        double det = p.x() * q.y() - p.y() * q.x();
        if (Math.abs(det) < Tolerances.GRAZE_ANGLE) {
            return Optional.empty();
        }
        return Optional.of(new Vect((a.speed() * q.y() - b.speed() * p.y()) / det,
                (p.x() * b.speed() - q.x() * a.speed()) / det));
    }
}
