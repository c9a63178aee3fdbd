package gizmoball.boardfile;

import gizmoball.model.Board;
import gizmoball.model.loop.BallView;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * The pairs of free balls a board file placed on each other, for as long as they have not separated: the loop
 * lets such a pair pass through each other, so the invariants must not call their overlap a violation until
 * they have come apart once (from then on they collide as usual, and an overlap is a violation again).
 */
final class PassingPairs {
    /** Overlap up to this is touching (the board's own tolerance for placing balls). */
    private static final double TOUCHING = 1e-9;

    private final Set<Set<String>> pairs = new HashSet<>();

    /** The overlapping pairs of the board as loaded. */
    PassingPairs(Board board) {
        List<BallView> free = board.balls().stream().filter(b -> !b.isCaptured()).toList();
        for (int i = 0; i < free.size(); i++) {
            for (int j = i + 1; j < free.size(); j++) {
                if (overlap(free.get(i), free.get(j))) {
                    pairs.add(Set.of(free.get(i).name(), free.get(j).name()));
                }
            }
        }
    }

    /** Forgets the pairs that have separated (or of which a ball was captured or is gone). */
    void update(Board board) {
        pairs.removeIf(pair -> {
            List<BallView> balls = pair.stream().map(board::ball).flatMap(Optional::stream).toList();
            return balls.size() < 2 || balls.get(0).isCaptured() || balls.get(1).isCaptured()
                    || !overlap(balls.get(0), balls.get(1));
        });
    }

    Set<Set<String>> pairs() {
        return Set.copyOf(pairs);
    }

    private static boolean overlap(BallView a, BallView b) {
        return Math.sqrt(a.position().distanceSquared(b.position())) < 2 * Board.BALL_RADIUS - TOUCHING;
    }
}
