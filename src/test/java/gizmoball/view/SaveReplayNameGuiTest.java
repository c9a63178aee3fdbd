package gizmoball.view;

import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.JFileChooser;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/** Issue 40 item 12: Save replay suggests a name after the board loaded, not untitled. */
class SaveReplayNameGuiTest extends WindowOnFiles {
    @Test
    void saveReplaySuggestsTheBoardsName() throws Exception {
        launch(Files.copy(Path.of("boards", "default.txt"), dir.resolve("default.txt")));
        SwingUtilities.invokeLater(() -> Gui.menuItem(window.menus(), "Save replay...").doClick(0));
        JFileChooser chooser = awaitChooser();
        assertThat(onEdt(() -> chooser.getSelectedFile().getName())).isEqualTo("default.replay.json");
        onEdt(chooser::cancelSelection);
    }
}
