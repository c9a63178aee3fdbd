package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.LoopViews;

import java.util.List;

import org.junit.jupiter.api.Test;

import physics.Vect;

/**
 * A ball beyond a cluster's limit (docs/design.md, "Contact clusters"): the solve moves only the cluster's balls, so a
 * ball beyond that presses in is a still surface and one that moves away a surface moving as it does. With every
 * surface still or moving away, the balls at rest close on no row: the solve always has an answer.
 */
class ClusterLimitTest {
    private static final double R = Board.BALL_RADIUS;

    /**
     * A column of touching balls on the floor, one more than a cluster holds, the top one moving at {@code vy}: the
     * cluster of the bottom ball holds all but that one.
     */
    private static ContactCluster columnWithTopBeyond(double vy) {
        LoopSettings settings = LoopSettings.STANDARD;
        int below = settings.clusterBalls();
        Board board = new Board();
        board.setFriction(0, 0);
        for (int k = 0; k <= below; k++) {
            board.addBall("B" + k, 10, Board.SIZE - R - 2 * R * k, 0, k == below ? vy : 0);
        }
        LoopView view = LoopViews.of(board);
        ContactCluster cluster = new ContactCluster().gather(view, List.of(view.ball("B0")),
                (ball, within, into) -> into.addAll(view.balls()), Ball::velocity, ball -> true,
                Tolerances.PLACEMENT, settings);
        assertThat(cluster.balls()).hasSize(below).extracting(Ball::name).doesNotContain("B" + below);
        return cluster;
    }

    private static ClusterRow beyondRow(ContactCluster cluster) {
        return cluster.rows().stream().filter(row -> row.other() instanceof ClusterRow.Other.Beyond).findFirst()
                .orElseThrow();
    }

    @Test
    void aBallBeyondThatPressesInIsStill() {
        ContactCluster cluster = columnWithTopBeyond(5);

        ClusterRow row = beyondRow(cluster);
        assertThat(row.normal()).isEqualTo(new Vect(0, 1));
        assertThat(row.surfaceSpeed()).isZero();
        // The floor, the column on it and the ball beyond still on top: the balls at rest close on no row.
        assertThat(cluster.rows()).allSatisfy(each -> assertThat(each.surfaceSpeed()).isLessThanOrEqualTo(0));
    }

    @Test
    void aBallBeyondThatMovesAwayIsFollowedAtItsSpeed() {
        ClusterRow row = beyondRow(columnWithTopBeyond(-5));

        assertThat(row.surfaceSpeed()).isEqualTo(-5);
    }
}
