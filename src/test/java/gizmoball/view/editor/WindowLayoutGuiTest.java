package gizmoball.view.editor;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.view.Gui;
import java.awt.Component;
import java.awt.Rectangle;
import java.awt.Window;
import java.util.Arrays;
import java.util.Optional;
import javax.swing.AbstractButton;
import javax.swing.JButton;
import javax.swing.JColorChooser;
import javax.swing.JDialog;
import javax.swing.JScrollPane;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Issue 23, items 14 and 16: the smallest window, the side panels' scroll bars, the colour chooser's place. */
class WindowLayoutGuiTest {
    private BuildWindow w;

    @BeforeEach
    void open() {
        w = BuildWindow.open();
    }

    @AfterEach
    void close() {
        for (Window window : Window.getWindows()) {
            onEdt(window::dispose);
        }
    }

    private JScrollPane side(Component inside) {
        return onEdt(() -> (JScrollPane) SwingUtilities.getAncestorOfClass(JScrollPane.class, inside));
    }

    /** Item 14: at 400 px wide the board was gone and Play and Build off screen; now the window stops short. */
    @Test
    void theWindowStopsAtASizeWhereBuildModeIsWhole() {
        onEdt(() -> w.window.setSize(400, 300));
        await("the window to be laid out", () -> w.window.getWidth() >= 400 && w.panel.getWidth() > 0);
        onEdt(() -> w.window.validate());

        Rectangle window = onEdt(() -> new Rectangle(w.window.getSize()));
        assertThat(window.width).isEqualTo(onEdt(() -> w.window.getMinimumSize().width)).isGreaterThan(400);
        assertThat(onEdt(() -> Math.min(w.panel.getWidth(), w.panel.getHeight()))).as("board view")
                .isGreaterThanOrEqualTo(240);
        JScrollPane east = side(w.build.properties());
        JScrollPane west = side(w.build.palette());
        assertThat(onEdt(() -> east.getWidth())).isGreaterThanOrEqualTo(onEdt(() -> w.build.properties()
                .getPreferredSize().width));
        assertThat(onEdt(() -> west.getViewport().getWidth())).isGreaterThanOrEqualTo(onEdt(() -> w.build.palette()
                .getPreferredSize().width));
        for (String button : new String[] {"Play", "Build"}) {
            AbstractButton b = onEdt(() -> Gui.find(w.window.toolBar(), AbstractButton.class,
                    x -> button.equals(x.getText())).orElseThrow());
            Rectangle bounds = onEdt(() -> SwingUtilities.convertRectangle(b.getParent(), b.getBounds(),
                    w.window.getContentPane()));
            assertThat(bounds.x + bounds.width).as(button).isLessThanOrEqualTo(onEdt(() ->
                    w.window.getContentPane().getWidth()));
        }
    }

    /** Item 16: a side that fits shows no scroll bar. */
    @Test
    void aSideThatFitsHasNoScrollBar() {
        onEdt(() -> w.window.setSize(1280, 1000));
        await("the window to grow", () -> w.window.getHeight() >= 1000);
        onEdt(() -> w.window.validate());

        // A side that needed its bar in the smaller window loses it once the layout has caught up.
        await("the palette's bar to go", () -> !onEdt(() -> side(w.build.palette()).getVerticalScrollBar().isVisible()));
        await("the properties' bar to go",
                () -> !onEdt(() -> side(w.build.properties()).getVerticalScrollBar().isVisible()));
    }

    /** Item 16: the colour chooser opens centred on the window, not beside it. */
    @Test
    void theColourChooserOpensCentredOnTheWindow() {
        onEdt(() -> w.board.addGizmo(GizmoKind.SQUARE, "S1", 3, 3));
        onEdt(() -> w.build.controller().select("S1"));
        JButton choose = onEdt(() -> EditorGui.find(w.build.properties(), JButton.class, "gizmo.colour.choose"));
        // A new window may still be growing into its build-mode size; a chooser centred on it before it is done is
        // left where it was (a CI run found one 431.5 px off: half of what the window then grew by).
        Rectangle[] last = {onEdt(() -> w.window.getBounds())};
        int[] unchanged = {0};
        await("the window to keep its bounds for 200 ms", () -> {
            Rectangle now = w.window.getBounds();
            unchanged[0] = now.equals(last[0]) ? unchanged[0] + 1 : 0;
            last[0] = now;
            return unchanged[0] >= 10;
        });
        // The chooser is placed on the window as it is when the button is pressed: compared with those bounds, and
        // both named if it fails (under a loaded CI machine the window has been seen to move on after the wait).
        Rectangle[] atClick = new Rectangle[1];
        SwingUtilities.invokeLater(() -> {
            atClick[0] = w.window.getBounds();
            choose.doClick(0);
        });
        await("the chooser", () -> chooser().isPresent());
        JDialog dialog = chooser().orElseThrow();

        Rectangle[] seen = new Rectangle[2];
        try {
            await("the chooser centred on the window, within 40 px", () -> {
                seen[0] = w.window.getBounds();
                seen[1] = dialog.getBounds();
                return centredOn(seen[1], atClick[0]) || centredOn(seen[1], seen[0]);
            });
        } catch (AssertionError e) {
            throw new AssertionError(e.getMessage() + ": the window was at " + atClick[0] + " when the button was "
                    + "pressed and is at " + seen[0] + ", the chooser at " + seen[1], e);
        }
    }

    private static boolean centredOn(Rectangle dialog, Rectangle window) {
        return Math.abs(dialog.getCenterX() - window.getCenterX()) < 40
                && Math.abs(dialog.getCenterY() - window.getCenterY()) < 40;
    }

    private static Optional<JDialog> chooser() {
        return Arrays.stream(Window.getWindows())
                .filter(x -> x instanceof JDialog d && d.isShowing()
                        && Gui.find(d.getContentPane(), JColorChooser.class, c -> true).isPresent())
                .map(JDialog.class::cast).findFirst();
    }
}
