package gizmoball.view.editor;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.editor.Editor;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.view.BoardPanel;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.event.KeyEvent;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** Build mode's overlay painted into an image (headless): issue 12, items 10 and 16. */
class BuildOverlayPaintTest {
    private static final int SIZE = 612;   // 30 px per L inside the 6 px margin

    private final Board board = new Board();
    private final Editor editor = Editor.of(board);

    private BufferedImage render() {
        return render(SIZE);
    }

    /** The panel painted into an image {@code width} wide: wider than the panel shows what is drawn past it. */
    private BufferedImage render(int width) {
        BoardPanel panel = panel();
        BufferedImage image = new BufferedImage(width, SIZE, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        panel.paint(g);
        g.dispose();
        return image;
    }

    private BoardPanel panel() {
        BoardPanel panel = BoardPanel.of(board);
        panel.setSize(SIZE, SIZE);
        panel.addOverlay(new BuildOverlay(editor, () -> true));
        return panel;
    }

    /** A refused footprint over a gizmo of any colour shows both near-white and near-black pixels. */
    @Test
    void aRefusedFootprintReadsOverEveryGizmoColour() {
        for (GizmoKind kind : new GizmoKind[] {GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE}) {
            board.clear();
            board.addGizmo(kind, "G", 5, 5);
            editor.setTool(Tool.SQUARE);
            editor.hover(5.5, 5.5);
            assertThat(editor.preview().orElseThrow().fits()).isFalse();
            BufferedImage image = render();
            Point2D a = panel().transform().toScreen(5, 5);
            Point2D b = panel().transform().toScreen(6, 6);
            int light = 0;
            int dark = 0;
            int all = 0;
            for (int x = (int) a.getX() + 4; x < (int) b.getX() - 4; x++) {
                for (int y = (int) a.getY() + 4; y < (int) b.getY() - 4; y++) {
                    Color c = new Color(image.getRGB(x, y));
                    int min = Math.min(c.getRed(), Math.min(c.getGreen(), c.getBlue()));
                    int max = Math.max(c.getRed(), Math.max(c.getGreen(), c.getBlue()));
                    light += min > 220 ? 1 : 0;
                    dark += max < 40 ? 1 : 0;
                    all++;
                }
            }
            assertThat(light).as("near-white pixels over a %s", kind).isGreaterThan(all / 20);
            assertThat(dark).as("near-black pixels over a %s", kind).isGreaterThan(all / 20);
        }
    }

    /** The selection outline of a bottom-row gizmo with keys is whole: its label no longer covers its edge. */
    @Test
    void theKeyLabelLeavesABottomRowGizmosOutlineWhole() {
        board.addGizmo(GizmoKind.SQUARE, "S", 5, 19);
        board.bindKey(KeyEvent.VK_Z, KeyEdge.DOWN, "S");
        editor.select("S");
        BufferedImage image = render();
        BoardPanel panel = panel();
        Point2D bottomLeft = panel.transform().toScreen(5, 20);
        Point2D bottomRight = panel.transform().toScreen(6, 20);
        // The outline stands 3 px off the footprint, 3.5 px wide: its bottom edge's middle row is 3 px below.
        int y = (int) Math.round(bottomLeft.getY() + 3);
        for (int x = (int) bottomLeft.getX() - 1; x <= (int) bottomRight.getX() + 1; x++) {
            Color c = new Color(image.getRGB(x, y));
            assertThat(c.getRed() > 200 && c.getGreen() > 180 && c.getBlue() < 120)
                    .as("outline colour at (%d, %d): %s", x, y, c).isTrue();
        }
    }

    /** A key label beside a gizmo in the right-hand column is moved in to stay whole on the board. */
    @Test
    void aKeyLabelAtTheRightEdgeStaysOnTheBoard() {
        board.addGizmo(GizmoKind.SQUARE, "S", 19, 5);
        editor.select("S");
        BufferedImage without = render(SIZE + 300);
        board.bindKey(KeyEvent.VK_ENTER, KeyEdge.DOWN, "S");
        board.bindKey(KeyEvent.VK_ENTER, KeyEdge.UP, "S");
        BufferedImage with = render(SIZE + 300);
        double boardRight = panel().transform().toScreen(Board.SIZE, 0).getX();
        int drawn = 0;
        int pastTheBoard = 0;
        for (int x = 0; x < with.getWidth(); x++) {
            for (int y = 0; y < SIZE; y++) {
                if (with.getRGB(x, y) != without.getRGB(x, y)) {
                    drawn++;
                    pastTheBoard += x >= boardRight ? 1 : 0;
                }
            }
        }
        assertThat(drawn).as("pixels of the key label").isGreaterThan(100);
        assertThat(pastTheBoard).as("pixels of the key label right of the board's edge at %.0f", boardRight).isZero();
    }
}
