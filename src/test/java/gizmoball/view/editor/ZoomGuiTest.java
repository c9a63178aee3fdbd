package gizmoball.view.editor;

import static gizmoball.view.Gui.await;
import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.editor.Tool;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.view.Gui;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.geom.Point2D;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Issue 23, zoom through the real window: Ctrl+wheel zooms about the pointer by whole pixels per L, the view
 * scrolls, a real mouse click lands in the cell under it at that zoom, and Zoom to fit (Ctrl+0) brings the whole
 * board back.
 */
class ZoomGuiTest {
    private BuildWindow w;

    @BeforeEach
    void open() {
        w = BuildWindow.open();
        // Tall enough for the whole palette: a side that scrolls at the default size may gain or lose its bar as
        // the zoomed view relays the window out, and move the board under the pointer by half the bar's width.
        onEdt(() -> w.window.setSize(1280, 1000));
        await("the window to grow", () -> w.window.getHeight() >= 1000);
        onEdt(() -> w.window.validate());
    }

    @AfterEach
    void close() {
        if (w != null) {   // null when the test was skipped for want of a display
            w.close();
        }
    }

    private double scale() {
        return onEdt(() -> w.panel.transform().scale());
    }

    private void ctrlWheel(double x, double y, int rotation) {
        onEdt(() -> {
            Point2D p = w.panel.transform().toScreen(x, y);
            w.panel.dispatchEvent(new MouseWheelEvent(w.panel, MouseEvent.MOUSE_WHEEL, System.currentTimeMillis(),
                    InputEvent.CTRL_DOWN_MASK, (int) Math.round(p.getX()), (int) Math.round(p.getY()), 0, false,
                    MouseWheelEvent.WHEEL_UNIT_SCROLL, 3, rotation));
        });
    }

    /** Where the board point shows, in pixels from the top-left corner of what shows of the view. */
    private Point2D inViewport(double x, double y) {
        return onEdt(() -> {
            Point2D p = w.panel.transform().toScreen(x, y);
            Rectangle visible = w.panel.getVisibleRect();
            return new Point2D.Double(p.getX() - visible.x, p.getY() - visible.y);
        });
    }

    @Test
    void ctrlWheelZoomsAboutThePointerAndClicksStillLandInTheirCell() throws Exception {
        double fit = scale();
        Point2D before = inViewport(11.5, 9.5);
        ctrlWheel(11.5, 9.5, -1);
        ctrlWheel(11.5, 9.5, -1);
        double zoomed = scale();
        assertThat(zoomed).as("whole pixels per L, larger").isGreaterThan(fit).isEqualTo(Math.rint(zoomed));
        assertThat(onEdt(() -> w.window.zoom().zoomed())).isTrue();
        assertThat(onEdt(() -> w.panel.getWidth() > w.panel.getVisibleRect().width)).as("it scrolls").isTrue();
        Point2D after = inViewport(11.5, 9.5);
        assertThat(after.getX()).as("the point under the pointer stays there").isCloseTo(before.getX(), within(2.0));
        assertThat(after.getY()).isCloseTo(before.getY(), within(2.0));

        w.clickTool(Tool.SQUARE);
        Point cell = w.cellOnScreen(11, 9);
        Robot robot = new Robot();
        robot.mouseMove(cell.x, cell.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        Gui.await("the real click placed a square", () -> !w.board.gizmos().isEmpty());
        Gizmo placed = onEdt(() -> w.board.gizmos().get(0));
        assertThat(placed.x() + "," + placed.y()).isEqualTo("11,9");

        Gui.clickMenu(w.window.menus(), "Zoom to fit");
        assertThat(scale()).isEqualTo(fit);
        assertThat(onEdt(() -> w.window.zoom().zoomed())).isFalse();
        ctrlWheel(10, 10, -1);
        ctrlWheel(10, 10, 5);
        assertThat(scale()).as("zooming out stops at fit").isEqualTo(fit);
    }
}
