package gizmoball.view;

import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Robot;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JScrollPane;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/**
 * Issue 40 item 9: the problems of a load get the room their lines need, before the notes, with every reason whole;
 * the notes' heading says that their lines load (a ball placed on another is not refused). Leaves a screenshot.
 */
class LoadProblemsLayoutGuiTest extends WindowOnFiles {
    private static final String FIVE_BAD_TWO_NOTES = """
            Square S 5 5
            Ball B 5.5 5.5 0 0
            Ball B2 10 10 0 0
            Ball B3 10.2 10 0 0
            color S #99b3ff
            Rhombus X 5 5
            Circle C 30 30
            Triangle T1 1 1 extra
            Connect S Nowhere
            """;

    @Test
    void everyProblemShowsWholeAndTheNotesSayTheirLinesLoad() throws Exception {
        launch(write("board.txt", GOOD));
        Path bad = write("bad.txt", FIVE_BAD_TWO_NOTES);
        SwingUtilities.invokeLater(() -> app.files().open(bad));
        JDialog dialog = awaitProblemsDialog();
        Gui.sleep(300);
        Files.createDirectories(Path.of("build", "screenshots"));
        ImageIO.write(new Robot().createScreenCapture(onEdt(() -> dialog.getBounds())), "png",
                Path.of("build", "screenshots", "load-problems.png").toFile());

        assertThat(listed(dialog, "loadProblems.list")).hasSize(5);
        for (String name : new String[] {"loadProblems.list", "loadProblems.notes.list"}) {
            JList<?> list = onEdt(() -> Gui.find(dialog.getContentPane(), JList.class,
                    l -> name.equals(l.getName())).orElseThrow());
            JScrollPane scroll = onEdt(() -> (JScrollPane) SwingUtilities.getAncestorOfClass(JScrollPane.class, list));
            assertThat(onEdt(() -> list.getPreferredSize().width)).as(name + ": no line runs off the side")
                    .isLessThanOrEqualTo(onEdt(() -> scroll.getViewport().getWidth()));
            assertThat(onEdt(() -> list.getPreferredSize().height)).as(name + ": every line in sight")
                    .isLessThanOrEqualTo(onEdt(() -> scroll.getViewport().getHeight()));
        }
        assertThat(onEdt(() -> Gui.find(dialog.getContentPane(), JLabel.class,
                l -> "loadProblems.notes.heading".equals(l.getName())).orElseThrow().getText()))
                .isEqualTo("2 notes on lines that load:");
    }
}
