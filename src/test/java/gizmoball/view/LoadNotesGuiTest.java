package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.app.Gizmoball;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Rgb;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/** The notes of a load (lines read in another implementation's way) in the problems dialog (needs a display). */
class LoadNotesGuiTest extends WindowOnFiles {
    private static final String NOTES_ONLY = "Square S 1 1\ncolor S #99b3ff\nBall B 5 5\n";
    private static final String NOTES_AND_ERRORS = "Connect S C\nSquare S 1 1\nCircle C 3 3\nRhombus X 5 5\n";

    @Test
    void aFileWithOnlyNotesLoadsAndThenListsThemWithLineNumbers() throws Exception {
        launch(Files.writeString(dir.resolve("empty.txt"), ""));
        Path file = Files.writeString(dir.resolve("peer.txt"), NOTES_ONLY);

        SwingUtilities.invokeLater(() -> app.files().open(file));
        JDialog dialog = awaitProblemsDialog();
        assertThat(onEdt(() -> window.session().board().gizmos().stream().map(Gizmo::colour).toList()))
                .as("loaded before the notes show").containsExactly(Optional.of(new Rgb(0x99, 0xb3, 0xff)));
        assertThat(onEdt(dialog::getTitle)).isEqualTo("Notes on peer.txt");
        assertThat(listed(dialog, "loadProblems.notes.list")).containsExactly(
                "line 2: color S #99b3ff   <- read as Colour S 153 179 255",
                "line 3: Ball B 5 5   <- no velocity given: the ball starts at rest");
        assertThat(onEdt(() -> Gui.find(dialog.getContentPane(), JList.class,
                l -> "loadProblems.list".equals(l.getName())))).as("no problems section").isEmpty();
        click(dialog, LoadProblemsDialog.OK);
        await("the dialog closed", () -> !onEdt(dialog::isShowing));
    }

    @Test
    void errorsAndNotesShareTheDialogUnderTheirOwnHeadings() throws Exception {
        launch(Files.writeString(dir.resolve("empty.txt"), ""));
        Path file = Files.writeString(dir.resolve("mixed.txt"), NOTES_AND_ERRORS);

        SwingUtilities.invokeLater(() -> app.files().open(file));
        JDialog dialog = awaitProblemsDialog();
        assertThat(listed(dialog, "loadProblems.list")).containsExactly(
                "line 4: Rhombus X 5 5   <- Rhombus X: an extension of another implementation, not part of the format");
        assertThat(listed(dialog, "loadProblems.notes.list")).containsExactly(
                "line 1: Connect S C   <- applied after line 3, which defines C");
        assertThat(onEdt(() -> Gui.find(dialog.getContentPane(), JLabel.class,
                l -> "loadProblems.notes.heading".equals(l.getName())).orElseThrow().getText()))
                .isEqualTo("A note on a line that loads:");
        click(dialog, LoadProblemsDialog.SKIP);
        await("the board without line 4", () -> onEdt(() -> window.session().board().connections().size()) == 1);
    }
}
