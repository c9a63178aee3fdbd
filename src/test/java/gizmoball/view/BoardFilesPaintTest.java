package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gizmoball.boardfile.BoardFiles;
import gizmoball.model.Board;
import gizmoball.model.gizmo.AbsorberView;
import gizmoball.model.gizmo.BumperView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.PortalView;
import gizmoball.model.gizmo.SpawnerView;
import gizmoball.model.loop.BallView;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import physics.Vect;

/**
 * Every board that ships with the game, and every peer board we can load, is painted with each gizmo and
 * ball in its colour where the model puts it (headless: the panel is painted into an image).
 */
class BoardFilesPaintTest {
    private static final int SIZE = 492;   // 24 px per L: a pixel sampled 0.1 L inside a shape is clear of its antialiased edge
    private static final Path PEER_BOARDS = Path.of("..", "shared", "peer-boards");

    static Stream<Path> sampleBoards() throws IOException {
        try (Stream<Path> files = Files.list(Path.of("boards"))) {
            return files.filter(p -> p.toString().endsWith(".txt")).sorted().toList().stream();
        }
    }

    static Stream<Path> peerBoards() throws IOException {
        if (!Files.isDirectory(PEER_BOARDS)) {
            return Stream.of(PEER_BOARDS);   // one case, skipped below with the reason
        }
        try (Stream<Path> files = Files.list(PEER_BOARDS)) {
            return files.filter(Files::isRegularFile).sorted().toList().stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sampleBoards")
    void sampleBoardLoadsCleanlyAndPaints(Path file) throws Exception {
        assertPaintedAsModelled(BoardFiles.load(file), file);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("peerBoards")
    void peerBoardPaintsWhatLoads(Path file) throws Exception {
        assumeTrue(Files.isRegularFile(file), "no peer boards at " + PEER_BOARDS.toAbsolutePath());
        assertPaintedAsModelled(BoardFiles.loadSkippingBadLines(file).board(), file);
    }

    private static void assertPaintedAsModelled(Board board, Path file) {
        BoardPanel panel = BoardPanel.of(board);
        panel.setSize(SIZE, SIZE);
        BufferedImage image = new BufferedImage(SIZE, SIZE, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        panel.paint(g);
        g.dispose();
        BoardTransform t = panel.transform();
        for (Gizmo gizmo : board.gizmos()) {
            if (gizmo.kind() == GizmoKind.LEFT_FLIPPER || gizmo.kind() == GizmoKind.RIGHT_FLIPPER) {
                continue;
            }
            // A triangle at its centroid, a sink, a drop target or a plunger on its frame (the centre is a hole, a
            // bull's-eye, a rod), a portal or a spawner on the side away from its mouth (the spawner's arrow points
            // to it), a spinner on its bar (lying flat as loaded) half-way out from its hub, anything else at its
            // centre.
            Vect inside = gizmo instanceof BumperView b && gizmo.kind() == GizmoKind.TRIANGLE ? centroid(b.outline())
                    : gizmo instanceof PortalView portal
                    ? new Vect(gizmo.x() + 0.5, gizmo.y() + 0.5).minus(portal.facing().times(0.4))
                    : gizmo instanceof SpawnerView spawner
                    ? centre(gizmo).minus(spawner.mouth(0).minus(centre(gizmo)).times(0.8))
                    : gizmo.kind() == GizmoKind.SINK
                    || gizmo.kind() == GizmoKind.DROP_TARGET
                    || gizmo instanceof AbsorberView absorber && absorber.plunger().isPresent()
                    ? new Vect(gizmo.x() + 0.1, gizmo.y() + 0.5)
                    : gizmo.kind() == GizmoKind.SPINNER ? new Vect(gizmo.x() + 0.5, gizmo.y() + 1)
                    : new Vect(gizmo.x() + gizmo.width() / 2.0, gizmo.y() + gizmo.height() / 2.0);
            assertThat(pixel(image, t, inside)).as("%s: %s at %s", file, gizmo.name(), inside)
                    .isEqualTo(BoardPainter.colourOf(gizmo));
        }
        for (BallView ball : board.balls()) {
            // Several balls held in one corner carry a count label; balls loaded on each other cross outlines.
            if (board.balls().stream().noneMatch(other -> other != ball
                    && other.position().distanceSquared(ball.position()) < 4 * Board.BALL_RADIUS * Board.BALL_RADIUS)) {
                assertThat(pixel(image, t, ball.position())).as("%s: ball %s", file, ball.name())
                        .isEqualTo(BoardPainter.BALL);
            }
        }
    }

    private static Vect centre(Gizmo gizmo) {
        return new Vect(gizmo.x() + gizmo.width() / 2.0, gizmo.y() + gizmo.height() / 2.0);
    }

    private static Vect centroid(List<Vect> corners) {
        Vect sum = new Vect(0, 0);
        for (Vect c : corners) {
            sum = sum.plus(c);
        }
        return sum.times(1.0 / corners.size());
    }

    private static Color pixel(BufferedImage image, BoardTransform t, Vect at) {
        Point2D p = t.toScreen(at.x(), at.y());
        return new Color(image.getRGB((int) p.getX(), (int) p.getY()));
    }
}
