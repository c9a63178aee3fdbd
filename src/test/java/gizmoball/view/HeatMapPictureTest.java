package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.boardfile.BoardFiles;
import gizmoball.lab.HeatGrid;
import gizmoball.lab.Lab;
import gizmoball.lab.LabProgress;
import gizmoball.lab.LabResult;
import gizmoball.lab.LabSettings;
import gizmoball.model.Board;
import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/**
 * The heat map glows where the balls went and nowhere else: a ball with no gravity and no friction bouncing straight
 * up and down the column x = 10 between the floor and the ceiling, on an empty board.
 */
class HeatMapPictureTest {
    private static final int SIDE = 400;

    @Test
    void glowsAlongTheBallsPathAndNowhereElse() throws Exception {
        Board board = BoardFiles.load("column", "Gravity 0\nFriction 0 0\nBall B 10 10 0 15\n");
        LabResult result = Lab.run(board, "column", new LabSettings(1, 1, 5, Board.DEFAULT_TICK), LabProgress.NONE);
        BufferedImage blank = HeatMapPicture.image(BoardFiles.load("empty", ""), new HeatGrid(), SIDE, "empty");
        BufferedImage picture = ImageIO.read(new ByteArrayInputStream(HeatMapPicture.png(
                HeatMapPicture.image(board.copy(), result.autoplayerHeat(), SIDE, "column"))));

        assertThat(picture.getWidth()).isEqualTo(SIDE);
        assertThat(picture.getHeight()).isEqualTo(SIDE + HeatMapPicture.KEY_HEIGHT);
        BoardTransform t = BoardTransform.fit(SIDE, SIDE, 6);
        for (double y : new double[] {2, 6, 14, 18}) {
            // On the path: lit, warmer than the veiled floor of a picture with no heat.
            assertThat(red(picture, t, 10, y)).as("on the path at y %s", y).isGreaterThan(red(blank, t, 10, y) + 60);
            // Three L to the side: as dark as the picture with no heat.
            assertThat(red(picture, t, 7, y)).as("off the path at y %s", y).isEqualTo(red(blank, t, 7, y));
        }
    }

    private static int red(BufferedImage image, BoardTransform t, double x, double y) {
        var at = t.toScreen(x, y);
        return new Color(image.getRGB((int) at.getX(), (int) at.getY())).getRed();
    }
}
