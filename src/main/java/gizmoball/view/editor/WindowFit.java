package gizmoball.view.editor;

import gizmoball.session.Mode;

import javax.swing.JFrame;
import java.awt.Dimension;
import java.awt.GraphicsConfiguration;
import java.awt.Insets;
import java.awt.Rectangle;
import java.awt.Toolkit;

/**
 * Makes room for the side panels: the window is sized for play mode, and in build mode the palette and the
 * properties would otherwise squeeze the board. Entering build mode widens the window to its preferred size
 * (within the screen); leaving it puts the old size back, unless the player resized the window meanwhile.
 */
public final class WindowFit {
    private final JFrame window;
    private Dimension beforeBuild;
    private Dimension grownTo;

    public WindowFit(JFrame window) {
        this.window = window;
    }

    public void modeChanged(Mode mode) {
        if (mode == Mode.BUILD) {
            Dimension now = window.getSize();
            Dimension wanted = window.getPreferredSize();
            Rectangle screen = usableScreen();
            int width = Math.min(Math.max(now.width, wanted.width), screen.width);
            int height = Math.min(Math.max(now.height, wanted.height), screen.height);
            if (width != now.width || height != now.height) {
                beforeBuild = now;
                window.setSize(width, height);
                grownTo = window.getSize();
                keepOnScreen(screen);
            }
        } else if (beforeBuild != null) {
            if (window.getSize().equals(grownTo)) {
                window.setSize(beforeBuild);
            }
            beforeBuild = null;
        }
    }

    private Rectangle usableScreen() {
        GraphicsConfiguration config = window.getGraphicsConfiguration();
        Rectangle bounds = config.getBounds();
        Insets insets = Toolkit.getDefaultToolkit().getScreenInsets(config);
        return new Rectangle(bounds.x + insets.left, bounds.y + insets.top,
                bounds.width - insets.left - insets.right, bounds.height - insets.top - insets.bottom);
    }

    private void keepOnScreen(Rectangle screen) {
        int x = Math.max(screen.x, Math.min(window.getX(), screen.x + screen.width - window.getWidth()));
        int y = Math.max(screen.y, Math.min(window.getY(), screen.y + screen.height - window.getHeight()));
        window.setLocation(x, y);
    }
}
