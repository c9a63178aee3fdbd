package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardFiles;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.view.editor.ToolIcon;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.util.Arrays;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Every kind of gizmo is whole in every layer (docs/design.md, "Adding a gizmo kind"): where the compiler cannot
 * ask (a placement tool, pixels actually drawn, a file line read back), this test does, for each kind.
 */
class EveryKindTest {
    private static final int SIZE = 612;   // 30 px per L inside the 6 px margin
    private static final int X = 5;
    private static final int Y = 6;

    @ParameterizedTest
    @EnumSource(GizmoKind.class)
    void hasExactlyOnePlacementTool(GizmoKind kind) {
        assertThat(Arrays.stream(Tool.values()).filter(t -> t.kind().equals(java.util.Optional.of(kind))))
                .hasSize(1);
    }

    @ParameterizedTest
    @EnumSource(GizmoKind.class)
    void isPaintedInItsColourInsideItsFootprintAndNowhereElse(GizmoKind kind) {
        Board board = boardWith(kind);
        BoardPanel panel = BoardPanel.of(board);
        panel.setSize(SIZE, SIZE);
        BufferedImage image = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        panel.setGridVisible(false);
        panel.paint(g);
        g.dispose();
        Gizmo gizmo = board.gizmo("G").orElseThrow();
        int inColour = 0;
        int outside = 0;
        for (double x = 0.05; x < Board.SIZE; x += 0.1) {
            for (double y = 0.05; y < Board.SIZE; y += 0.1) {
                Point2D p = panel.transform().toScreen(x, y);
                Color c = new Color(image.getRGB((int) p.getX(), (int) p.getY()));
                boolean inFootprint = x > gizmo.x() && x < gizmo.x() + gizmo.width() && y > gizmo.y()
                        && y < gizmo.y() + gizmo.height();
                if (inFootprint && c.equals(BoardPainter.colourOf(kind))) {
                    inColour++;
                } else if (!inFootprint && !c.equals(BoardPainter.FLOOR)) {
                    outside++;
                }
            }
        }
        int footprintSamples = 100 * gizmo.width() * gizmo.height();
        assertThat(inColour).as("samples of the footprint in the kind's colour").isGreaterThan(footprintSamples / 10);
        assertThat(outside).as("samples outside the footprint not floor").isZero();
    }

    @ParameterizedTest
    @EnumSource(GizmoKind.class)
    void itsToolHasAnIconInTheKindsColour(GizmoKind kind) {
        Tool tool = Arrays.stream(Tool.values()).filter(t -> t.kind().equals(java.util.Optional.of(kind)))
                .findFirst().orElseThrow();
        ToolIcon icon = new ToolIcon(tool);
        BufferedImage image = new BufferedImage(icon.getIconWidth(), icon.getIconHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        icon.paintIcon(null, g, 0, 0);
        g.dispose();
        long inColour = 0;
        for (int x = 0; x < image.getWidth(); x++) {
            for (int y = 0; y < image.getHeight(); y++) {
                if (new Color(image.getRGB(x, y)).equals(BoardPainter.colourOf(kind))) {
                    inColour++;
                }
            }
        }
        assertThat(inColour).as("pixels of the icon in the kind's colour").isGreaterThan(20);
    }

    @ParameterizedTest
    @EnumSource(GizmoKind.class)
    void isWrittenToAFileAndReadBackAsItself(GizmoKind kind) throws Exception {
        Board board = boardWith(kind);
        if (kind.rotates()) {
            board.rotate("G");
        }
        Board back = BoardFiles.load("test", BoardFiles.toText(board));
        Gizmo read = back.gizmo("G").orElseThrow();
        assertThat(read.kind()).isEqualTo(kind);
        assertThat(read.rotation()).isEqualTo(kind.rotates() ? 1 : 0);
        assertThat(BoardFiles.toText(back)).isEqualTo(BoardFiles.toText(board));
    }

    private static Board boardWith(GizmoKind kind) {
        Board board = new Board();
        if (kind == GizmoKind.ABSORBER) {
            board.addAbsorber("G", X, Y, X + 3, Y + 2);
        } else {
            board.addGizmo(kind, "G", X, Y);
        }
        return board;
    }
}
