package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.TriggerSource;
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

    /**
     * Issue 40 item 2: out of a portal's pair the trail starts afresh, with no streak across the board. The ball
     * leaves at sqrt(6^2 + 1.5^2) L/s with no gravity or friction, so its whole trail is within LENGTH - 1 ticks of
     * that speed of it.
     */
    @Test
    void aBallOutOfAPortalStartsANewTrailWhereItReappears() {
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addGizmo(GizmoKind.PORTAL, "P1", 4, 10);
        board.addGizmo(GizmoKind.PORTAL, "P2", 14, 10);
        board.set("P1", Setting.Pair.with("P2"));
        board.addBall("B", 4.5 + 0.125, 10 - 0.25 - 1.05, 1.5, 6);
        trails.setEnabled(true);
        for (int i = 0; i < 25; i++) {
            board.tick(Board.DEFAULT_TICK);
        }
        Vect ball = board.ball("B").orElseThrow().position();
        assertThat(ball.x()).as("through the pair").isGreaterThan(12);
        double reach = (BallTrails.LENGTH - 1) * Math.hypot(6, 1.5) * Board.DEFAULT_TICK;
        assertThat(trails.trail("B")).isNotEmpty()
                .allSatisfy(p -> assertThat(p.minus(ball).length()).isLessThanOrEqualTo(reach + 1e-9));
    }

    /** Issue 40 item 2: a ball an absorber takes and fires in one tick has no streak from where it went in. */
    @Test
    void aBallFiredInTheTickItWasTakenStartsANewTrail() {
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addAbsorber("A", 0, 19, 20, 20);
        board.connect(TriggerSource.named("A"), "A");
        board.addBall("B", 5.5, 18.5, 0, 5);
        trails.setEnabled(true);
        double furthest = 0;
        for (int i = 0; i < 40; i++) {
            board.tick(Board.DEFAULT_TICK);
            List<Vect> trail = trails.trail("B");
            for (int j = 1; j < trail.size(); j++) {
                furthest = Math.max(furthest, trail.get(j).minus(trail.get(j - 1)).length());
            }
        }
        assertThat(board.ball("B").orElseThrow().position().x()).as("fired from the right").isGreaterThan(19);
        assertThat(furthest).as("the longest step of any trail, L").isLessThan(2);
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
