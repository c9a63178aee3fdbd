package gizmoball.view.editor;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.view.BoardTransform;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** Issue 23, item 12: the trigger label at the right wall was cut to its first letter; now it is read whole. */
class AimPreviewLabelTest {
    @Test
    void aLabelAtTheRightWallMovesInToBeReadWhole() {
        Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
        FontMetrics m = g.getFontMetrics();
        BoardTransform t = BoardTransform.fit(612, 612, 6);
        String text = "OuterWalls \u2192 RF1";

        for (Point2D at : new Point2D[] {t.toScreen(20, 10), t.toScreen(0, 0), t.toScreen(19.9, 0.1)}) {
            Rectangle2D box = AimPreviewOverlay.labelBox(m, t, at, text);
            assertThat(t.component().contains(box)).as("label at %s", at).isTrue();
            assertThat(box.getWidth()).isGreaterThan(m.stringWidth(text));
        }
    }
}
