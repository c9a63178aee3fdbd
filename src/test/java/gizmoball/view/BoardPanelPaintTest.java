package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Rgb;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.util.Optional;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Renders a BoardPanel into an image (no display needed) and reads the pixels where the model says things are. */
class BoardPanelPaintTest {
    private static final int SIZE = 612;   // 30 px per L inside the 6 px margin
    private static final int Z = 90;

    private final Board board = new Board();
    private BoardPanel panel;

    @BeforeEach
    void board() {
        board.addGizmo(GizmoKind.SQUARE, "S", 2, 2);
        board.addGizmo(GizmoKind.CIRCLE, "C", 5, 5);
        board.addGizmo(GizmoKind.TRIANGLE, "T", 8, 3);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 6, 15);
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addBall("B", 10.5, 10.5, 0, 0);
        board.bindKey(Z, KeyEdge.DOWN, "LF");
        panel = BoardPanel.of(board);
        panel.setSize(SIZE, SIZE);
    }

    private BufferedImage render() {
        BufferedImage image = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        panel.paint(g);
        g.dispose();
        return image;
    }

    private Color at(BufferedImage image, double x, double y) {
        Point2D p = panel.transform().toScreen(x, y);
        return new Color(image.getRGB((int) p.getX(), (int) p.getY()));
    }

    @Test
    void eachGizmoAndBallIsPaintedInItsColourWhereTheModelPutsIt() {
        BufferedImage image = render();

        assertThat(at(image, 2.5, 2.5)).isEqualTo(BoardPainter.colourOf(GizmoKind.SQUARE));
        assertThat(at(image, 5.5, 5.5)).isEqualTo(BoardPainter.colourOf(GizmoKind.CIRCLE));
        assertThat(at(image, 8.25, 3.25)).isEqualTo(BoardPainter.colourOf(GizmoKind.TRIANGLE));
        assertThat(at(image, 8.8, 3.8)).as("the triangle's empty half").isEqualTo(BoardPainter.FLOOR);
        assertThat(at(image, 6.25, 16)).as("flipper at rest, along its box's left edge")
                .isEqualTo(BoardPainter.colourOf(GizmoKind.LEFT_FLIPPER));
        assertThat(at(image, 12.5, 19.5)).isEqualTo(BoardPainter.colourOf(GizmoKind.ABSORBER));
        assertThat(at(image, 10.5, 10.5)).isEqualTo(BoardPainter.BALL);
        assertThat(at(image, 15.5, 5.5)).isEqualTo(BoardPainter.FLOOR);
        assertThat(new Color(image.getRGB(2, 2))).as("outside the walls").isEqualTo(BoardPainter.BACKGROUND);
    }

    @Test
    void theFlipperIsPaintedAtItsCurrentAngle() {
        board.keyDown(Z);
        for (int i = 0; i < 20; i++) {   // 1/3 s: the 90 degree swing takes 1/12 s, the highlight 1/4 s
            board.tick(Board.DEFAULT_TICK);
        }
        BufferedImage image = render();

        assertThat(at(image, 7.5, 15.25)).as("along its box's top edge")
                .isEqualTo(BoardPainter.colourOf(GizmoKind.LEFT_FLIPPER));
        assertThat(at(image, 6.25, 16.5)).isEqualTo(BoardPainter.FLOOR);
    }

    @Test
    void aTriggeredGizmoFlashesNearlyWhiteWithAGlowAndFadesWithinAFifthOfASecond() {
        Color square = BoardPainter.colourOf(GizmoKind.SQUARE);
        board.trigger("S");
        BufferedImage atTrigger = render();
        ticks(5);   // 83 ms: half-way through the 150 ms fade
        BufferedImage halfWay = render();
        ticks(5);   // 167 ms: over
        BufferedImage after = render();

        Color lit = at(atTrigger, 2.5, 2.5);
        for (int[] channel : new int[][] {{lit.getRed(), square.getRed()}, {lit.getGreen(), square.getGreen()},
                {lit.getBlue(), square.getBlue()}}) {
            assertThat(channel[0]).as("fill at the trigger, most of the way to white")
                    .isGreaterThanOrEqualTo(channel[1] + (int) (0.8 * (255 - channel[1])));
        }
        Color glow = at(atTrigger, 2.5, 1.93);
        assertThat(glow.getGreen()).as("the glow just outside the square").isGreaterThan(BoardPainter.FLOOR.getGreen() + 120);
        Color fading = at(halfWay, 2.5, 2.5);
        assertThat(fading.getGreen()).isStrictlyBetween(square.getGreen(), lit.getGreen());
        assertThat(at(after, 2.5, 2.5)).isEqualTo(square);
        assertThat(at(after, 2.5, 1.93)).isEqualTo(BoardPainter.FLOOR);
    }

    @Test
    void aGizmoWithItsOwnColourIsPaintedInItAndFlashesFromIt() {
        Color own = new Color(0x20, 0x40, 0x60);
        board.setColour("S", Optional.of(new Rgb(0x20, 0x40, 0x60)));
        board.setColour("LF", Optional.of(new Rgb(0x99, 0xb3, 0xff)));
        BufferedImage image = render();
        assertThat(at(image, 2.5, 2.5)).isEqualTo(own);
        assertThat(at(image, 6.25, 16.5)).as("the flipper at rest, along its left side").isEqualTo(new Color(0x99b3ff));
        assertThat(at(image, 5.5, 5.5)).as("no colour of its own").isEqualTo(BoardPainter.colourOf(GizmoKind.CIRCLE));

        board.trigger("S");
        Color lit = at(render(), 2.5, 2.5);
        assertThat(lit.getRed()).as("brighter than its own colour").isGreaterThan(own.getRed() + 100);
        assertThat(lit.getBlue()).isGreaterThan(own.getBlue() + 100);
        ticks(10);
        board.setColour("S", Optional.empty());
        assertThat(at(render(), 2.5, 2.5)).isEqualTo(BoardPainter.colourOf(GizmoKind.SQUARE));
    }

    private void ticks(int n) {
        for (int i = 0; i < n; i++) {
            board.tick(Board.DEFAULT_TICK);
        }
    }

    @Test
    void severalBallsHeldByAnAbsorberShowHowManyOnTheBallInItsCorner() {
        Board held = new Board();
        held.addAbsorber("A", 0, 18, 20, 20);
        held.addBall("B1", 5, 18.5, 0, 0);
        panel = BoardPanel.of(held);
        panel.setSize(SIZE, SIZE);
        assertThat(darkPixelsOnBall(render(), 19.75, 19.75)).as("one ball: no label").isZero();

        held.addBall("B2", 7, 18.5, 0, 0);
        held.addBall("B3", 9, 18.5, 0, 0);

        assertThat(held.balls()).allSatisfy(b -> assertThat(b.isCaptured()).isTrue());
        assertThat(darkPixelsOnBall(render(), 19.75, 19.75)).as("three balls: a label").isPositive();
    }

    /** Issue 12 item 16: the count sat below the ball, half outside it, dark on the dark absorber. */
    @Test
    void theCountOfHeldBallsIsInkedInsideTheBallAndCentredOnIt() {
        Board held = new Board();
        held.addAbsorber("A", 0, 18, 20, 20);
        for (int i = 0; i < 3; i++) {
            held.addBall("B" + i, 5 + 2 * i, 18.5, 0, 0);
        }
        panel = BoardPanel.of(held);
        panel.setSize(SIZE, SIZE);
        BufferedImage image = render();
        Point2D centre = panel.transform().toScreen(19.75, 19.75);
        double pixelsPerL = panel.transform().scale();
        double radius = Board.BALL_RADIUS * pixelsPerL;
        int reach = (int) Math.ceil(2.5 * radius);
        double sumX = 0;
        double sumY = 0;
        int ink = 0;
        for (int px = (int) centre.getX() - reach; px <= (int) centre.getX() + reach; px++) {
            for (int py = (int) centre.getY() - reach; py <= (int) centre.getY() + reach; py++) {
                double d0 = Math.hypot(px + 0.5 - centre.getX(), py + 0.5 - centre.getY());
                physics.Vect onBoard = panel.transform().toBoard(px + 0.5, py + 0.5);
                if (d0 > 2 * radius || onBoard.x() >= Board.SIZE || onBoard.y() >= Board.SIZE) {
                    continue;   // the ball and the absorber around it, not the margin beyond the walls
                }
                Color c = new Color(image.getRGB(px, py));
                // The digits' colour, far darker than the ball, its edge and the absorber.
                if (c.getRed() < 64 && c.getGreen() < 64 && c.getBlue() < 64) {
                    double d = Math.hypot(px + 0.5 - centre.getX(), py + 0.5 - centre.getY());
                    assertThat(d).as("ink at (%d, %d) is on the ball", px, py).isLessThanOrEqualTo(radius);
                    sumX += px + 0.5;
                    sumY += py + 0.5;
                    ink++;
                }
            }
        }
        assertThat(ink).isPositive();
        // One digit's ink is symmetric about its centre to within a pixel or two.
        assertThat(Math.hypot(sumX / ink - centre.getX(), sumY / ink - centre.getY())).isLessThan(2.0);
    }

    /** Pixels well inside the ball (away from its outline) much darker than the ball's colour. */
    private int darkPixelsOnBall(BufferedImage image, double x, double y) {
        int dark = 0;
        double r = 0.8 * Board.BALL_RADIUS;
        for (double dx = -r; dx <= r; dx += 0.02) {
            for (double dy = -r; dy <= r; dy += 0.02) {
                if (dx * dx + dy * dy <= r * r && at(image, x + dx, y + dy).getRed() < 128) {
                    dark++;
                }
            }
        }
        return dark;
    }

    @Test
    void theGridIsDrawnOnlyWhenAskedFor() {
        Point2D line = panel.transform().toScreen(15, 5.5);
        int x = (int) line.getX();
        int y = (int) line.getY();
        assertThat(new Color(render().getRGB(x, y))).isEqualTo(BoardPainter.FLOOR);

        panel.setGridVisible(true);
        BufferedImage image = render();

        assertThat(new Color(image.getRGB(x, y))).isNotEqualTo(BoardPainter.FLOOR);
        assertThat(at(image, 15.5, 5.5)).as("between grid lines").isEqualTo(BoardPainter.FLOOR);
    }

    @Test
    void theBoardKeepsItsAspectRatioAndIsCentredInAWidePanel() {
        panel.setSize(1000, 500);
        BufferedImage image = new BufferedImage(1000, 500, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        panel.paint(g);
        g.dispose();

        BoardTransform t = panel.transform();
        assertThat(t.scale()).isEqualTo(24);   // (500 - 2 * 6) / 20, rounded down
        assertThat(t.toScreen(10, 10)).isEqualTo(new Point2D.Double(500, 250));
        Point2D square = t.toScreen(2.5, 2.5);
        assertThat(new Color(image.getRGB((int) square.getX(), (int) square.getY())))
                .isEqualTo(BoardPainter.colourOf(GizmoKind.SQUARE));
        assertThat(new Color(image.getRGB(100, 250))).as("left of the board").isEqualTo(BoardPainter.BACKGROUND);
    }
}
