package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import physics.Vect;

/** View > Ball trails, painted into an image (no display needed). */
class BallTrailsTest {
    private static final int SIZE = 612;
    private final Board board = new Board();
    private final BallTrails trails = new BallTrails(board);

    @Test
    void aTrailHoldsTheBallsLastPositionsAndIsPaintedBehindIt() {
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addBall("B", 2.5, 10.5, 12, 0);
        trails.setEnabled(true);
        List<Vect> positions = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            board.tick(Board.DEFAULT_TICK);
            positions.add(board.ball("B").orElseThrow().position());
        }
        assertThat(trails.trail("B")).containsExactlyElementsOf(positions.subList(40 - BallTrails.LENGTH, 40));

        BoardPanel panel = BoardPanel.of(board);
        panel.addUnderlay(trails);
        panel.setSize(SIZE, SIZE);
        BufferedImage image = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        panel.paint(g);
        g.dispose();
        // 12 L/s: the ball is at x = 10.5; 0.1 s back it was at 9.3, where only the trail is now.
        Vect ball = board.ball("B").orElseThrow().position();
        Point2D behind = panel.transform().toScreen(ball.x() - 1.2, ball.y());
        Color trail = new Color(image.getRGB((int) behind.getX(), (int) behind.getY()));
        assertThat(trail).isNotEqualTo(BoardPainter.FLOOR);
        assertThat(trail.getBlue()).isGreaterThan(BoardPainter.FLOOR.getBlue() + 60);
    }

    @Test
    void anEditStartsTheTrailsAfreshAndACapturedBallHasNone() {
        board.addBall("B", 10.5, 10.5, 0, 0);
        trails.setEnabled(true);
        board.tick(Board.DEFAULT_TICK);
        assertThat(trails.trail("B")).hasSize(1);
        board.addGizmo(GizmoKind.SQUARE, "S", 2, 2);
        assertThat(trails.trail("B")).isEmpty();

        board.addAbsorber("A", 0, 19, 20, 20);
        board.addBall("C", 5.5, 18.5, 0, 5);
        for (int i = 0; i < 30; i++) {
            board.tick(Board.DEFAULT_TICK);
        }
        assertThat(board.ball("C").orElseThrow().isCaptured()).isTrue();
        assertThat(trails.trail("C")).isEmpty();
    }

    @Test
    void aDisabledTrailRecordsNothing() {
        board.addBall("B", 10.5, 10.5, 3, 0);
        trails.setEnabled(true);
        trails.setEnabled(false);
        board.tick(Board.DEFAULT_TICK);
        assertThat(trails.trail("B")).isEmpty();
    }
}
