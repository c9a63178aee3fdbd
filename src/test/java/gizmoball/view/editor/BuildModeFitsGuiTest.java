package gizmoball.view.editor;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.app.Gizmoball;
import gizmoball.controller.Settings;
import gizmoball.editor.Tool;
import gizmoball.session.Mode;
import gizmoball.view.Gui;
import java.awt.Dimension;
import java.awt.Rectangle;
import java.awt.Robot;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.UUID;
import java.util.prefs.Preferences;
import javax.imageio.ImageIO;
import javax.swing.JScrollPane;
import javax.swing.JTabbedPane;
import javax.swing.JToggleButton;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Issue 40, item 1: build mode fits the window it opens in. At the first size (the window as it opens on the
 * screen, with no size remembered) and at the minimum size every tool of the palette is in sight without
 * scrolling. At the first size the properties panel too fits, without a scroll bar, for the common selections: nothing
 * (the Board tab), a flipper with its keys, an absorber with its plunger, a ball (the Selection tab). Each size leaves
 * a screenshot of both modes in build/screenshots.
 */
class BuildModeFitsGuiTest {
    private static final Path SHOTS = Path.of("build", "screenshots");

    private final Preferences node = Preferences.userRoot().node("/gizmoball-test/" + UUID.randomUUID());
    private Gizmoball app;

    @BeforeEach
    void open() {
        Gui.assumeDisplay();
        app = Gizmoball.launch(Path.of("boards", "default.txt"), new Settings(node));
        await("the window", () -> app.window().isShowing() && app.window().boardPanel().getWidth() > 100);
    }

    @AfterEach
    void close() throws Exception {
        Gui.closeAllWindows();   // and waits for their closing, which writes to the node
        node.removeNode();
    }

    @Test
    void everyToolIsInSightAtTheFirstSize() throws Exception {
        shoot("fits-first-play");
        onEdt(() -> app.session().setMode(Mode.BUILD));
        settle();
        shoot("fits-first-build");
        assertEverythingInSight();
        // The picture of docs/build-mode.md: the left flipper's connections and keys drawn.
        onEdt(() -> app.build().controller().select("LF"));
        shoot("fits-first-build-lf");
    }

    @Test
    void thePropertiesFitAtTheFirstSizeForTheCommonSelections() throws Exception {
        onEdt(() -> app.session().setMode(Mode.BUILD));
        settle();
        for (String selected : new String[] {null, "LF", "Plunger", "B"}) {
            onEdt(() -> app.build().controller().select(selected));
            settle();
            shoot("fits-first-properties-" + selected);
            JTabbedPane tabs = onEdt(() -> EditorGui.find(app.build().properties(), JTabbedPane.class,
                    "properties.tabs"));
            assertThat(onEdt(() -> tabs.getTitleAt(tabs.getSelectedIndex())))
                    .as("the tab with " + selected + " selected")
                    .isEqualTo(selected == null ? "Board" : "Selection");
            JScrollPane east = scrollPane(app.build().properties());
            int needed = onEdt(() -> app.build().properties().getPreferredSize().height);
            int room = onEdt(() -> east.getViewport().getHeight());
            assertThat(needed).as("the properties panel's height with " + selected + " selected")
                    .isLessThanOrEqualTo(room);
            assertThat(onEdt(() -> east.getVerticalScrollBar().isVisible()))
                    .as("the properties' scroll bar with " + selected + " selected").isFalse();
        }
    }

    @Test
    void everyToolIsInSightAtTheMinimumSize() throws Exception {
        Dimension smallest = onEdt(() -> app.window().getMinimumSize());
        onEdt(() -> app.window().setSize(smallest));
        await("the smallest window", () -> app.window().getSize().equals(smallest));
        settle();
        shoot("fits-minimum-play");
        onEdt(() -> app.session().setMode(Mode.BUILD));
        settle();
        shoot("fits-minimum-build");
        assertEverythingInSight();
        onEdt(() -> app.build().controller().select("LF"));
        settle();
        shoot("fits-minimum-build-lf");
    }

    private void assertEverythingInSight() {
        PalettePanel palette = app.build().palette();
        JScrollPane west = scrollPane(palette);
        for (Tool tool : Tool.values()) {
            JToggleButton button = onEdt(() -> EditorGui.find(palette, JToggleButton.class, "tool." + tool.name()));
            Rectangle inView = onEdt(() -> SwingUtilities.convertRectangle(button.getParent(), button.getBounds(),
                    west));
            Rectangle view = onEdt(() -> west.getViewport().getBounds());
            assertThat(view.contains(inView)).as(tool + " at " + inView + " in the palette's view " + view).isTrue();
        }
        assertThat(onEdt(() -> west.getVerticalScrollBar().isVisible())).as("the palette's scroll bar").isFalse();
    }

    private static JScrollPane scrollPane(java.awt.Component inside) {
        return onEdt(() -> (JScrollPane) SwingUtilities.getAncestorOfClass(JScrollPane.class, inside));
    }

    /** Waits for the window to keep its size and layout for 200 ms. */
    private void settle() {
        Rectangle[] last = {null};
        int[] same = {0};
        await("the window to settle", () -> {
            app.window().validate();
            Rectangle now = app.window().getBounds();
            same[0] = now.equals(last[0]) ? same[0] + 1 : 0;
            last[0] = now;
            return same[0] >= 10;
        });
    }

    private void shoot(String name) throws Exception {
        Gui.sleep(300);
        Files.createDirectories(SHOTS);
        Rectangle bounds = onEdt(() -> app.window().getBounds());
        ImageIO.write(new Robot().createScreenCapture(bounds), "png", SHOTS.resolve(name + ".png").toFile());
    }
}
