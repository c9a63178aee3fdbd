package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.FontMetrics;
import java.awt.image.BufferedImage;
import javax.swing.JLabel;
import org.junit.jupiter.api.Test;

/** The status line's choices of what to show, laid out at a given width (no display needed). */
class StatusLineTest {
    private static final String LONG_NAME = "a-board-with-a-really-quite-remarkably-long-name-for-testing.txt";
    private static final String MESSAGE = "Loaded " + LONG_NAME + " without its 3 bad lines";

    private final StatusLine line = new StatusLine();

    private JLabel label(String name) {
        return Gui.find(line, JLabel.class, l -> name.equals(l.getName())).orElseThrow();
    }

    private void layOut(int width) {
        line.setSize(width, line.getPreferredSize().height);
        line.doLayout();
    }

    @Test
    void theFrameRateShowsOnlyWhileTheGameRuns() {
        line.show("b.txt", "Play", false, "1x", 1.5, 34);
        assertThat(line.text()).doesNotContain("fps").isEqualTo("b.txt   Play - stopped at 1x   t = 1.50 s");

        line.show("b.txt", "Play", true, "1x", 1.5, 34);
        assertThat(line.text()).contains(" 34 fps");

        line.show("b.txt", "Build", false, "1x", 0, 2);
        assertThat(line.text()).doesNotContain("fps");
    }

    @Test
    void aLongNameIsShortenedInTheMiddleSoTheMessageShowsWhole() {
        line.show(LONG_NAME, "Play", false, "1x", 0, 0);
        line.showMessage("Loaded without its 3 bad lines");
        layOut(700);

        JLabel message = label("status.message");
        assertThat(message.getWidth()).isGreaterThanOrEqualTo(message.getPreferredSize().width);
        String board = label("status.board").getText();
        assertThat(board).contains("\u2026").endsWith(".txt").startsWith("a-board");
        assertThat(board.length()).isLessThan(LONG_NAME.length());
        assertThat(label("status.state").isVisible()).isTrue();
    }

    @Test
    void atFourHundredPixelsTheMessageHasPriorityOverEveryFact() {
        line.show("b.txt", "Play", false, "1x", 12.25, 0);
        line.showMessage("Loaded b.txt without its 3 bad lines");
        layOut(400);

        JLabel message = label("status.message");
        assertThat(message.getWidth()).as("the message is not cut").isGreaterThanOrEqualTo(
                message.getPreferredSize().width);
        assertThat(message.getX() + message.getWidth()).isLessThanOrEqualTo(400);
    }

    @Test
    void aMessageLongerThanTheLineLosesItsMiddleNotItsEnd() {
        line.show(LONG_NAME, "Play", false, "1x", 0, 0);
        line.showMessage(MESSAGE);
        layOut(300);

        JLabel message = label("status.message");
        assertThat(message.getText()).contains("\u2026").startsWith("Loaded").endsWith("its 3 bad lines");
        assertThat(message.getX() + message.getPreferredSize().width).isLessThanOrEqualTo(300);
        assertThat(line.message()).isEqualTo(MESSAGE);
    }

    @Test
    void theTooltipSaysTheWholeLine() {
        line.show(LONG_NAME, "Play", true, "1x", 2, 60);
        line.showMessage(MESSAGE);
        layOut(300);

        assertThat(line.getToolTipText()).isEqualTo(line.text()).contains(LONG_NAME, MESSAGE, "Play - running at 1x");
    }

    @Test
    void middleEllipsisKeepsBothEndsAndFits() {
        FontMetrics metrics = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics()
                .getFontMetrics(new JLabel().getFont());
        String text = "abcdefghijklmnopqrstuvwxyz.txt";
        int width = metrics.stringWidth(text) / 2;

        String shortened = StatusLine.middleEllipsis(text, metrics, width);

        assertThat(metrics.stringWidth(shortened)).isLessThanOrEqualTo(width);
        assertThat(shortened).startsWith("abc").endsWith("z.txt").contains("\u2026");
        assertThat(StatusLine.middleEllipsis(text, metrics, 10_000)).isEqualTo(text);
    }
}
