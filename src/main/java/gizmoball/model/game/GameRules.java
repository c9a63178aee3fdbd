package gizmoball.model.game;

import gizmoball.model.gizmo.GizmoKind;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.Set;

/**
 * What a board says about its game: how many balls a game has, which absorbers are drains (a ball they capture is
 * lost), the points of the gizmos whose value is not their kind's ({@link Points#defaultFor}), the score at
 * which an extra ball is awarded, the nudge and its tilt, and how long after a launch a drained ball is saved. A board
 * with no drain is a sandbox: the score still counts, no game ends. Immutable; the board replaces it on each edit.
 * Names only, so it knows nothing of where the gizmos are: the board checks that a drain is an absorber, that the
 * nudge's keys drive nothing else, and forgets a deleted gizmo's entries ({@link #without}).
 *
 * @param ownPoints       gizmo name -> its value, only where it differs from its kind's
 * @param nudge           empty: the board cannot be nudged
 * @param tilt            when nudging tilts (only where the board has a nudge)
 * @param ballSaveSeconds seconds of play after a launch in which a drained ball is given back once; 0 for none
 */
public record GameRules(int ballsPerGame, Set<String> drains, Map<String, Integer> ownPoints,
                        OptionalLong extraBallAt, Optional<Nudge> nudge, Tilt tilt, double ballSaveSeconds) {
    public static final int DEFAULT_BALLS = 3;
    public static final int MAX_BALLS = 99;
    public static final double MAX_BALL_SAVE_SECONDS = 30;
    /** What a board has until its file or its author says otherwise: a sandbox of three balls. */
    public static final GameRules DEFAULT = new GameRules(DEFAULT_BALLS, Set.of(), Map.of(), OptionalLong.empty(),
            Optional.empty(), Tilt.DEFAULT, 0);

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
        if (!(ballSaveSeconds >= 0 && ballSaveSeconds <= MAX_BALL_SAVE_SECONDS)) {
            throw new IllegalArgumentException("a ball save lasts 0 (none) to " + (int) MAX_BALL_SAVE_SECONDS
                    + " seconds, not " + ballSaveSeconds);
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
        return new GameRules(balls, drains, ownPoints, extraBallAt, nudge, tilt, ballSaveSeconds);
    }

    public GameRules withDrain(String gizmo, boolean drain) {
        Set<String> changed = new HashSet<>(drains);
        if (drain) {
            changed.add(gizmo);
        } else {
            changed.remove(gizmo);
        }
        return new GameRules(ballsPerGame, changed, ownPoints, extraBallAt, nudge, tilt, ballSaveSeconds);
    }

    /** The gizmo scores {@code points}; its kind's value is kept as no value of its own. */
    public GameRules withPoints(String gizmo, GizmoKind kind, int points) {
        Map<String, Integer> changed = new HashMap<>(ownPoints);
        if (points == Points.defaultFor(kind)) {
            changed.remove(gizmo);
        } else {
            changed.put(gizmo, points);
        }
        return new GameRules(ballsPerGame, drains, changed, extraBallAt, nudge, tilt, ballSaveSeconds);
    }

    /** @param score empty for no extra ball */
    public GameRules withExtraBallAt(OptionalLong score) {
        return new GameRules(ballsPerGame, drains, ownPoints, score, nudge, tilt, ballSaveSeconds);
    }

    /** @param newNudge empty for a board that cannot be nudged */
    public GameRules withNudge(Optional<Nudge> newNudge) {
        return new GameRules(ballsPerGame, drains, ownPoints, extraBallAt, newNudge, tilt, ballSaveSeconds);
    }

    public GameRules withTilt(Tilt newTilt) {
        return new GameRules(ballsPerGame, drains, ownPoints, extraBallAt, nudge, newTilt, ballSaveSeconds);
    }

    /** @param seconds 0 for no ball save */
    public GameRules withBallSave(double seconds) {
        return new GameRules(ballsPerGame, drains, ownPoints, extraBallAt, nudge, tilt, seconds);
    }

    /** The rules once the gizmo is gone: it is no drain and has no points of its own. */
    public GameRules without(String gizmo) {
        Map<String, Integer> points = new HashMap<>(ownPoints);
        points.remove(gizmo);
        return new GameRules(ballsPerGame, withDrain(gizmo, false).drains, points, extraBallAt, nudge, tilt,
                ballSaveSeconds);
    }
}
