package gizmoball.model.game;

import gizmoball.model.gizmo.GizmoKind;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.OptionalLong;
import java.util.Set;

/**
 * What a board says about its game: how many balls a game has, which absorbers are drains (a ball they capture is
 * lost), the points of the gizmos whose value is not their kind's ({@link Points#defaultFor}), and the score at
 * which an extra ball is awarded. A board with no drain is a sandbox: the score still counts, no game ends.
 * Immutable; the board replaces it on each edit. Names only, so it knows nothing of where the gizmos are: the
 * board checks that a drain is an absorber and forgets a deleted gizmo's entries ({@link #without}).
 *
 * @param ownPoints gizmo name -> its value, only where it differs from its kind's
 */
public record GameRules(int ballsPerGame, Set<String> drains, Map<String, Integer> ownPoints,
                        OptionalLong extraBallAt) {
    public static final int DEFAULT_BALLS = 3;
    public static final int MAX_BALLS = 99;
    /** What a board has until its file or its author says otherwise: a sandbox of three balls. */
    public static final GameRules DEFAULT = new GameRules(DEFAULT_BALLS, Set.of(), Map.of(), OptionalLong.empty());

    /** @throws IllegalArgumentException with the reason, in words for a board author, for values out of range */
    public GameRules {
        if (ballsPerGame < 1 || ballsPerGame > MAX_BALLS) {
            throw new IllegalArgumentException("a game has 1 to " + MAX_BALLS + " balls, not " + ballsPerGame);
        }
        ownPoints.forEach((gizmo, points) -> {
            if (Math.abs(points) > Points.LIMIT) {
                throw new IllegalArgumentException("points of " + gizmo + " must lie within -" + Points.LIMIT
                        + " and " + Points.LIMIT + ", not " + points);
            }
        });
        if (extraBallAt.isPresent() && (extraBallAt.getAsLong() < 1 || extraBallAt.getAsLong() > Long.MAX_VALUE / 2)) {
            throw new IllegalArgumentException("an extra ball is awarded at a score of 1 or more, not "
                    + extraBallAt.getAsLong());
        }
        drains = Set.copyOf(drains);
        ownPoints = Map.copyOf(ownPoints);
    }

    /** A game, not a sandbox: some absorber is a drain. */
    public boolean isGame() {
        return !drains.isEmpty();
    }

    public boolean isDrain(String gizmo) {
        return drains.contains(gizmo);
    }

    /** What a real hit on the gizmo scores. */
    public int pointsOf(String gizmo, GizmoKind kind) {
        return ownPoints.getOrDefault(gizmo, Points.defaultFor(kind));
    }

    public GameRules withBallsPerGame(int balls) {
        return new GameRules(balls, drains, ownPoints, extraBallAt);
    }

    public GameRules withDrain(String gizmo, boolean drain) {
        Set<String> changed = new HashSet<>(drains);
        if (drain) {
            changed.add(gizmo);
        } else {
            changed.remove(gizmo);
        }
        return new GameRules(ballsPerGame, changed, ownPoints, extraBallAt);
    }

    /** The gizmo scores {@code points}; its kind's value is kept as no value of its own. */
    public GameRules withPoints(String gizmo, GizmoKind kind, int points) {
        Map<String, Integer> changed = new HashMap<>(ownPoints);
        if (points == Points.defaultFor(kind)) {
            changed.remove(gizmo);
        } else {
            changed.put(gizmo, points);
        }
        return new GameRules(ballsPerGame, drains, changed, extraBallAt);
    }

    /** @param score empty for no extra ball */
    public GameRules withExtraBallAt(OptionalLong score) {
        return new GameRules(ballsPerGame, drains, ownPoints, score);
    }

    /** The rules once the gizmo is gone: it is no drain and has no points of its own. */
    public GameRules without(String gizmo) {
        Map<String, Integer> points = new HashMap<>(ownPoints);
        points.remove(gizmo);
        return new GameRules(ballsPerGame, withDrain(gizmo, false).drains, points, extraBallAt);
    }
}
