package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.Board;
import gizmoball.model.loop.BallReport;
import gizmoball.model.loop.TickReport;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/**
 * The overlay shows the model's own numbers for a scripted tick: one ball, no gravity or friction, 0.25 L from
 * the left wall at 30 L/s, so that it bounces once in the tick (after 1/120 s) and is then 0.5 L from the wall
 * going right, 19.25 L (0.6417 s) from the right wall.
 */
class PhysicsOverlayTest {
    private static final int SIZE = 612;
    private final Board board = new Board();
    private final PhysicsOverlay overlay = PhysicsOverlay.of(board);

    private TickReport scriptedTick() {
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addBall("B", 0.5, 10, -30, 0);
        overlay.setEnabled(true);
        board.tick(Board.DEFAULT_TICK);
        return board.lastTick();
    }

    @Test
    void thePanelShowsTheTicksCollisionsBallsAndSixStages() {
        TickReport r = scriptedTick();
        assertThat(r.collisions()).isEqualTo(1);
        assertThat(r.ballsAwake()).isEqualTo(1);
        assertThat(PhysicsOverlay.panelLines(r)).contains("collisions 1", "  0 at zero time", "  0 at once apart",
                        "balls awake 1", "balls asleep 0")
                .filteredOn(line -> line.matches("[1-6] .* us")).hasSize(6);
    }

    @Test
    void eachBallShowsItsNextCollisionFromTheReport() {
        TickReport r = scriptedTick();
        assertThat(r.balls()).hasSize(1);
        BallReport b = r.balls().get(0);
        assertThat(b.position().x()).isCloseTo(0.5, within(1e-9));
        assertThat(b.nextCollisionIn()).isCloseTo(19.25 / 30, within(1e-9));
        assertThat(b.nextCollisionAt().x()).isCloseTo(19.75, within(1e-9));
        assertThat(PhysicsOverlay.ballLabel(b)).isEqualTo("flying, hit in 0.642 s");

        BoardPanel panel = BoardPanel.of(board);
        panel.addOverlay(overlay);
        panel.setSize(SIZE, SIZE);
        BufferedImage image = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        panel.paint(g);
        g.dispose();
        // The ghost ball at the next collision: its ring crosses y = 10 at x = 19.5 (left edge of the ball there).
        Point2D ring = panel.transform().toScreen(19.5, 10);
        assertThat(brightest(image, ring, 2).getRed()).isGreaterThan(200);
        // The velocity arrow: 0.1 s of motion, 3 L to the right of the ball.
        Point2D arrow = panel.transform().toScreen(2.0, 10);
        assertThat(brightest(image, arrow, 1).getGreen()).isGreaterThan(200);
    }

    @Test
    void offItCostsTheLoopNothing() {
        scriptedTick();
        overlay.setEnabled(false);
        board.tick(Board.DEFAULT_TICK);
        assertThat(board.lastTick().balls()).as("no look-ahead, so no per-ball report").isEmpty();
    }

    private static Color brightest(BufferedImage image, Point2D at, int radius) {
        Color best = Color.BLACK;
        for (int dx = -radius; dx <= radius; dx++) {
            for (int dy = -radius; dy <= radius; dy++) {
                Color c = new Color(image.getRGB((int) at.getX() + dx, (int) at.getY() + dy));
                if (c.getRed() + c.getGreen() + c.getBlue() > best.getRed() + best.getGreen() + best.getBlue()) {
                    best = c;
                }
            }
        }
        return best;
    }

    /** Issue 23, item 10: Reset (a REPLACE) leaves no stale report; the first tick after it shows again. */
    @Test
    void afterResetTheOverlayShowsNoOldTickAndTheFirstNewTickShowsItsHits() {
        Board design = board.copy();
        scriptedTick();
        assertThat(overlay.shown().balls()).hasSize(1);

        board.replaceContents(design);

        assertThat(overlay.shown()).isEqualTo(TickReport.NONE);
        assertThat(PhysicsOverlay.panelLines(overlay.shown())).noneMatch(line -> line.startsWith("tick at"));
        board.setGravity(0);
        board.setFriction(0, 0);
        board.addBall("B", 0.5, 10, -30, 0);
        board.tick(Board.DEFAULT_TICK);
        assertThat(overlay.shown().balls()).singleElement()
                .satisfies(b -> assertThat(b.nextCollisionIn()).isCloseTo(19.25 / 30, within(1e-9)));
    }

    private static java.awt.FontMetrics metrics() {
        Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
        g.setFont(new java.awt.Font(java.awt.Font.MONOSPACED, java.awt.Font.PLAIN, 11));
        return g.getFontMetrics();
    }

    /** Issue 23, item 11: with room beside the board the panel goes there and covers nothing of it. */
    @Test
    void theTickPanelGoesBesideTheBoardWhereTheViewHasRoom() {
        BoardTransform t = BoardTransform.fit(1280, SIZE, 6);
        java.awt.geom.Rectangle2D box = overlay.panelBox(metrics(), t, PhysicsOverlay.panelLines(scriptedTick()));

        assertThat(box.getMaxX()).isLessThanOrEqualTo(t.board().getMinX());
        assertThat(box.getMinX()).isGreaterThanOrEqualTo(0);
    }

    /** Issue 23, item 11: without room beside the board the panel takes the corner where it covers least. */
    @Test
    void withoutRoomBesideTheBoardThePanelTakesTheCornerCoveringTheFewestGizmos() {
        board.addGizmo(gizmoball.model.gizmo.GizmoKind.CIRCLE, "C1", 3, 4);
        board.addGizmo(gizmoball.model.gizmo.GizmoKind.CIRCLE, "C2", 1, 1);
        board.addGizmo(gizmoball.model.gizmo.GizmoKind.CIRCLE, "C3", 16, 18);
        board.addGizmo(gizmoball.model.gizmo.GizmoKind.CIRCLE, "C4", 2, 17);
        BoardTransform t = BoardTransform.fit(SIZE, SIZE, 6);

        java.awt.geom.Rectangle2D box = overlay.panelBox(metrics(), t, PhysicsOverlay.panelLines(scriptedTick()));

        assertThat(box.getMinX()).as("on the right").isGreaterThan(t.board().getCenterX());
        assertThat(box.getMinY()).as("at the top").isLessThan(t.board().getCenterY());
        assertThat(t.board().contains(box)).isTrue();
    }

    /** Issue 23, item 11: a ball's label stays on the board, above the ball on the bottom row. */
    @Test
    void ballLabelsStayWithinTheBoard() {
        BoardTransform t = BoardTransform.fit(SIZE, SIZE, 6);
        String label = "flying, hit in 0.642 s";
        for (double[] at : new double[][] {{19.75, 10}, {0.25, 10}, {10, 19.75}, {0.25, 19.75}}) {
            java.awt.geom.Rectangle2D box = PhysicsOverlay.labelBox(metrics(), t, t.toScreen(at[0], at[1]), label,
                    java.util.List.of()).orElseThrow();
            assertThat(t.board().contains(box)).as("label of a ball at (%s, %s)", at[0], at[1]).isTrue();
        }
    }

    /** Issue 40 item 3: the stages are listed as the loop runs them (3 before 2), and the panel says so. */
    @Test
    void thePanelSaysItListsTheStagesInTheOrderTheyRun() {
        java.util.List<String> lines = PhysicsOverlay.panelLines(scriptedTick());
        assertThat(lines).contains("stages, in run order:");
        assertThat(lines.subList(lines.indexOf("stages, in run order:") + 1, lines.size()))
                .filteredOn(line -> line.matches("[1-6] .*")).extracting(line -> line.charAt(0))
                .containsExactly('1', '3', '2', '4', '5', '6');
    }

    /** Issue 40 item 3: balls close together get labels that overlap neither each other nor the panel. */
    @Test
    void labelsOfBallsCloseTogetherDoNotOverlap() {
        board.setGravity(0);
        board.setFriction(0, 0);
        for (int i = 0; i < 6; i++) {
            board.addBall("B" + i, 8.5 + 0.6 * i, 10 + 0.6 * (i % 2), 1, 0);
        }
        overlay.setEnabled(true);
        board.tick(Board.DEFAULT_TICK);
        BoardTransform t = BoardTransform.fit(SIZE, SIZE, 6);

        PhysicsOverlay.Layout layout = overlay.layout(metrics(), t, board.lastTick());

        assertThat(layout.labels()).isNotEmpty();
        java.util.List<java.awt.geom.Rectangle2D> boxes = new java.util.ArrayList<>(layout.labels().stream()
                .map(PhysicsOverlay.Label::box).toList());
        boxes.add(layout.panel());
        for (int i = 0; i < boxes.size(); i++) {
            for (int j = i + 1; j < boxes.size(); j++) {
                assertThat(boxes.get(i).intersects(boxes.get(j))).as("box %d over box %d", i, j).isFalse();
            }
        }
    }
}
