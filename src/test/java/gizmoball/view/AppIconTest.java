package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.GizmoKind;
import java.awt.Color;
import java.awt.Image;
import java.awt.image.BufferedImage;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The application icon is the game's own drawing (no display needed). */
class AppIconTest {
    private static Set<Integer> colours(BufferedImage image) {
        Set<Integer> rgb = new HashSet<>();
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                rgb.add(image.getRGB(x, y) & 0xffffff);
            }
        }
        return rgb;
    }

    @Test
    void itShowsTheGamesFloorBumperFlipperAndBallInTheirColours() {
        Set<Integer> seen = colours(AppIcon.image(256));
        assertThat(seen).contains(BoardPainter.FLOOR.getRGB() & 0xffffff, BoardPainter.BALL.getRGB() & 0xffffff,
                BoardPainter.colourOf(GizmoKind.CIRCLE).getRGB() & 0xffffff,
                BoardPainter.colourOf(GizmoKind.LEFT_FLIPPER).getRGB() & 0xffffff);
    }

    @Test
    void everyWindowSizeIsSquareAndOpaque() {
        for (Image image : AppIcon.windowImages()) {
            BufferedImage b = (BufferedImage) image;
            assertThat(b.getWidth()).isEqualTo(b.getHeight()).isBetween(16, 256);
            assertThat(new Color(b.getRGB(0, 0), true).getAlpha()).isEqualTo(255);
        }
    }
}
