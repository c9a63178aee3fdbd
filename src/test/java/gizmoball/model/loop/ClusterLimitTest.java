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

    /** Three balls in a column on the floor, touching, the top one moving at {@code vy}; the cluster holds two. */
    private static ContactCluster columnWithTopBeyond(double vy) {
        Board board = new Board();
        board.setFriction(0, 0);
        board.addBall("A", 10, Board.SIZE - R, 0, 0);
        board.addBall("B", 10, Board.SIZE - 3 * R, 0, 0);
        board.addBall("C", 10, Board.SIZE - 5 * R, 0, vy);
        LoopView view = LoopViews.of(board);
        return ContactCluster.around(view, List.of(view.ball("A")), Ball::velocity, ball -> true,
                Tolerances.PLACEMENT, 2);
    }

    private static ContactCluster.Row beyondRow(ContactCluster cluster) {
        return cluster.rows().stream().filter(row -> row.other() instanceof ContactCluster.Other.Beyond).findFirst()
                .orElseThrow();
    }

    @Test
    void aBallBeyondThatPressesInIsStill() {
        ContactCluster cluster = columnWithTopBeyond(5);

        assertThat(cluster.balls()).extracting(Ball::name).containsExactly("A", "B");
        ContactCluster.Row row = beyondRow(cluster);
        assertThat(row.normal()).isEqualTo(new Vect(0, 1));
        assertThat(row.surfaceSpeed()).isZero();
        // The floor, A on it and C still above B: the balls at rest close on none of the rows.
        assertThat(cluster.rows()).allSatisfy(each -> assertThat(each.surfaceSpeed()).isLessThanOrEqualTo(0));
    }

    @Test
    void aBallBeyondThatMovesAwayIsFollowedAtItsSpeed() {
        ContactCluster.Row row = beyondRow(columnWithTopBeyond(-5));

        assertThat(row.surfaceSpeed()).isEqualTo(-5);
    }
}
