package gizmoball.model;

import gizmoball.model.gizmo.BallTaking;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.SpatialIndex;
import gizmoball.model.loop.Tolerances;
import gizmoball.model.loop.TriggerSource;

import java.util.List;
import java.util.Optional;
import java.util.Set;

import physics.Vect;

/**
 * Where a gizmo or a ball may go: inside the board, on no other gizmo, no free ball inside a gizmo, a ball on an
 * absorber captured by it, names fresh and not reserved. The editor's previews, the editor's edits and the board
 * file loader all ask these rules, so none of them can accept what another refuses. Overlap itself is
 * {@link Overlaps}.
 */
final class PlacementRules {
    private final Registry registry;

    PlacementRules(Registry registry) {
        this.registry = registry;
    }

    /** See {@link Board#placementProblem}. */
    Optional<String> placementProblem(GizmoKind kind, int x, int y, int width, int height, String ignoring) {
        if (kind == null) {
            return Optional.of("no gizmo kind given");
        }
        if (kind.sizedByCorners()) {
            if (width < 1 || height < 1) {
                return Optional.of("an absorber must be at least one cell wide and high, not " + width + "x" + height);
            }
            return problemFor(kind.createSized("", x, y, width, height), ignoring);
        }
        if (width != kind.width() || height != kind.height()) {
            return Optional.of(kind.withArticle() + " is " + kind.width() + "x" + kind.height()
                    + " cells, not " + width + "x" + height);
        }
        GizmoBase candidate = kind.create("", x, y);
        GizmoBase moving = ignoring == null ? null : registry.gizmo(ignoring);
        if (moving != null && moving.kind() == kind) {
            for (int i = 0; i < moving.rotation(); i++) {
                candidate.rotateClockwise();
            }
        }
        return problemFor(candidate, ignoring);
    }

    /** Footprint inside the board, no other gizmo's cells (but the ignored one's), no free ball inside the shape. */
    Optional<String> problemFor(GizmoBase candidate, String ignoring) {
        return problemFor(candidate, ignoring, Set.of());
    }

    /** {@link #problemFor(GizmoBase, String)}, the balls named in {@code ballsIgnored} not in the way either. */
    Optional<String> problemFor(GizmoBase candidate, String ignoring, Set<String> ballsIgnored) {
        String what = (candidate.name().isEmpty() ? candidate.kind().withArticle()
                : "gizmo " + candidate.name()) + " at (" + candidate.x() + "," + candidate.y() + ")";
        for (int cx = candidate.x(); cx < candidate.x() + candidate.width(); cx++) {
            for (int cy = candidate.y(); cy < candidate.y() + candidate.height(); cy++) {
                if (!SpatialIndex.inside(cx, cy)) {
                    return Optional.of(what + " would leave the board: cell (" + cx + "," + cy + ") is outside it");
                }
            }
        }
        for (int cx = candidate.x(); cx < candidate.x() + candidate.width(); cx++) {
            for (int cy = candidate.y(); cy < candidate.y() + candidate.height(); cy++) {
                GizmoBase occupant = registry.index().at(cx, cy);
                if (occupant != null && !occupant.name().equals(ignoring)) {
                    return Optional.of(wouldOverlap(what, "gizmo", occupant.name()));
                }
            }
        }
        if (candidate.ballTaking() == BallTaking.HOLDS) {
            return Optional.empty();   // free balls under a new absorber are captured, not in the way
        }
        return ballOverlap(candidate, ballsIgnored).map(ball -> wouldOverlap(what, "ball", ball));
    }

    /** The first free ball that would be inside the candidate's body. */
    Optional<String> ballOverlap(GizmoBase candidate) {
        return ballOverlap(candidate, Set.of());
    }

    /** The first free ball, but those named in {@code ignoring}, that would be inside the candidate's body. */
    Optional<String> ballOverlap(GizmoBase candidate, Set<String> ignoring) {
        return registry.balls().stream()
                .filter(ball -> !ball.isCaptured() && !ignoring.contains(ball.name()))
                .filter(ball -> Overlaps.ballInGizmo(candidate, ball.position()))
                .map(Ball::name)
                .findFirst();
    }

    /**
     * Checks a ball position (for the ball named {@code name}, ignoring ball {@code ignoring}) and returns the
     * absorber that would capture it there (the gizmo that {@link BallTaking#HOLDS} balls there), or null.
     */
    GizmoBase captorOfPlacedBall(String name, Vect position, String ignoring, boolean ballsMayOverlap) {
        return captorOfPlacedBall(name, position, ignoring == null ? Set.of() : Set.of(ignoring), ballsMayOverlap);
    }

    /** {@link #captorOfPlacedBall(String, Vect, String, boolean)} ignoring every ball named in {@code ignoring}. */
    GizmoBase captorOfPlacedBall(String name, Vect position, Set<String> ignoring, boolean ballsMayOverlap) {
        String what = "ball " + name + " at (" + position.x() + "," + position.y() + ")";
        if (!insideBoard(position)) {
            throw new BoardEditException(what + " is outside the board (its centre must be at least "
                    + Arena.BALL_RADIUS + " L inside each wall)");
        }
        GizmoBase captor = null;
        for (GizmoBase gizmo : gizmosUnder(position)) {
            if (gizmo.ballTaking() == BallTaking.HOLDS) {
                captor = gizmo;
            } else {
                throw new BoardEditException(wouldOverlap(what, "gizmo", gizmo.name()));
            }
        }
        if (captor == null && !ballsMayOverlap) {
            Optional<Ball> other = freeBallUnder(position, ignoring);
            if (other.isPresent()) {
                throw new BoardEditException(wouldOverlap(what, "ball", other.get().name()));
            }
        }
        return captor;
    }

    /** Whether a ball could appear there now: inside the board, in no gizmo (absorbers too), on no free ball. */
    boolean freeForBall(Vect position) {
        return insideBoard(position) && gizmosUnder(position).isEmpty() && !onFreeBall(position);
    }

    /** Whether a ball centred there would overlap a free ball: a walk of the balls, no stream made (a spawner asks). */
    private boolean onFreeBall(Vect position) {
        List<Ball> balls = registry.ballList();
        for (int b = 0; b < balls.size(); b++) {
            Ball other = balls.get(b);
            if (!other.isCaptured() && Overlaps.balls(other.position(), position)) {
                return true;
            }
        }
        return false;
    }

    /** The gizmos a ball centred there would be inside, in the order of the cells around it. */
    private List<GizmoBase> gizmosUnder(Vect position) {
        double r = Arena.BALL_RADIUS;
        return registry.index().within(position.x() - r, position.y() - r, position.x() + r, position.y() + r)
                .stream()
                .filter(gizmo -> Overlaps.ballInGizmo(gizmo, position))
                .toList();
    }

    /** The first free ball, other than those named in {@code ignoring}, that a ball centred there would overlap. */
    private Optional<Ball> freeBallUnder(Vect position, Set<String> ignoring) {
        return registry.balls().stream()
                .filter(other -> !other.isCaptured() && !ignoring.contains(other.name())
                        && Overlaps.balls(other.position(), position))
                .findFirst();
    }

    /** The one wording of every overlap refusal: "gizmo S1 at (2,3) would overlap ball B". */
    static String wouldOverlap(String what, String kindOfThing, String name) {
        return what + " would overlap " + kindOfThing + " " + name;
    }

    /**
     * Whether a ball centred there lies inside the outer walls, overlapping them by no more than
     * {@link Tolerances#PLACEMENT}, as it may overlap a gizmo or a ball: a ball resting on the floor in play can lie
     * 3e-14 L into it, and a board saved then must load again.
     */
    static boolean insideBoard(Vect position) {
        double least = Arena.BALL_RADIUS - Tolerances.PLACEMENT;
        double most = Arena.SIZE - least;
        return position.x() >= least && position.x() <= most && position.y() >= least && position.y() <= most;
    }

    /** A name a new gizmo or ball may take: not empty, no whitespace, not the outer walls', not in use. */
    void requireFreshName(String name) {
        if (name == null || name.isEmpty() || name.chars().anyMatch(Character::isWhitespace)) {
            throw new BoardEditException("name '" + name + "' must be non-empty and contain no whitespace");
        }
        if (name.equals(TriggerSource.OuterWalls.NAME)) {
            throw new BoardEditException("name " + name + " is reserved for the outer walls");
        }
        if (registry.uses(name)) {
            throw new BoardEditException("name " + name + " is already used");
        }
    }
}
