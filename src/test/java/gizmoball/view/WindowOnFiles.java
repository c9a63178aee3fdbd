package gizmoball.view;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;

import gizmoball.app.Gizmoball;
import gizmoball.controller.Settings;
import gizmoball.model.gizmo.Gizmo;
import java.awt.Component;
import java.awt.Container;
import java.awt.Window;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;
import java.util.stream.Collectors;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JTextArea;
import javax.swing.JList;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the GUI tests of board files share: a folder of their own for the files, the game launched on one, and the
 * dialogs its window shows. They skip without a display, and every window is closed after each test.
 */
abstract class WindowOnFiles {
    /** A board that loads strictly: two gizmos and a ball. */
    static final String GOOD = "Square S1 2 2\nCircle C1 5 5\nBall B 10.5 5 0 0\n";

    @TempDir
    Path dir;
    Gizmoball app;
    GameWindow window;

    @BeforeEach
    void display() {
        Gui.assumeDisplay();
    }

    @AfterEach
    void close() {
        Gui.closeAllWindows();
    }

    /** Launches the game on the board file (null: none) and keeps its window. */
    void launch(Path file) {
        app = Gizmoball.launch(file);
        window = app.window();
    }

    /** As {@link #launch(Path)}, keeping the player's settings in {@code settings}. */
    void launch(Path file, Settings settings) {
        app = Gizmoball.launch(file, settings);
        window = app.window();
    }

    Path write(String name, String text) throws Exception {
        return Files.writeString(dir.resolve(name), text);
    }

    List<String> gizmoNames() {
        return onEdt(() -> window.session().board().gizmos().stream().map(Gizmo::name).toList());
    }

    static JDialog awaitDialog(Predicate<JDialog> which) {
        await("a dialog", () -> showingDialog(which).isPresent());
        return showingDialog(which).orElseThrow();
    }

    static Optional<JDialog> showingDialog(Predicate<JDialog> which) {
        return Arrays.stream(Window.getWindows())
                .filter(w -> w instanceof JDialog d && d.isShowing() && which.test(d))
                .map(JDialog.class::cast)
                .findFirst();
    }

    /** The dialog with the problems and notes of a load, once it shows. */
    static JDialog awaitProblemsDialog() {
        await("the problems dialog", () -> Gui.showingWindow("loadProblems").isPresent());
        return (JDialog) Gui.showingWindow("loadProblems").orElseThrow();
    }

    /** The items of the dialog's list of that name ("loadProblems.list": the problems; "loadProblems.notes.list"). */
    static List<String> listed(JDialog dialog, String name) {
        return onEdt(() -> {
            @SuppressWarnings("unchecked")
            JList<String> list = Gui.find(dialog.getContentPane(), JList.class, l -> name.equals(l.getName()))
                    .orElseThrow();
            List<String> items = new ArrayList<>();
            for (int i = 0; i < list.getModel().getSize(); i++) {
                items.add(list.getModel().getElementAt(i));
            }
            return items;
        });
    }

    static void click(JDialog dialog, String text) {
        onEdt(() -> Gui.find(dialog.getContentPane(), JButton.class, b -> text.equals(b.getText()))
                .orElseThrow().doClick(0));
    }

    static JFileChooser awaitChooser() {
        JDialog dialog = awaitDialog(d -> Gui.find(d.getContentPane(), JFileChooser.class, c -> true).isPresent());
        return onEdt(() -> Gui.find(dialog.getContentPane(), JFileChooser.class, c -> true).orElseThrow());
    }

    /** As if the player typed the name and pressed Save, with the chooser's filter as it is. */
    static void approve(JFileChooser chooser, File file) {
        onEdt(() -> {
            chooser.setSelectedFile(file);
            chooser.approveSelection();
        });
    }

    static List<String> buttons(JDialog dialog) {
        return onEdt(() -> all(dialog, JButton.class).stream().map(JButton::getText)
                .filter(t -> t != null && !t.isEmpty()).toList());
    }

    static String text(JDialog dialog) {
        return onEdt(() -> all(dialog, JLabel.class).stream().map(JLabel::getText).collect(Collectors.joining("\n"))
                + all(dialog, JTextArea.class).stream().map(JTextArea::getText).collect(Collectors.joining("\n")));
    }

    static <C extends Component> List<C> all(Container root, Class<C> type) {
        List<C> found = new ArrayList<>();
        for (Component c : root.getComponents()) {
            if (type.isInstance(c) && c.isVisible()) {
                found.add(type.cast(c));
            }
            if (c instanceof Container inner) {
                found.addAll(all(inner, type));
            }
        }
        return found;
    }
}
