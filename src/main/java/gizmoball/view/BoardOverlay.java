package gizmoball.view;

import java.awt.Graphics2D;

/** Something drawn over the board (selection, connections, placement preview); screen coordinates, antialiased. */
public interface BoardOverlay {
    void paint(Graphics2D g, BoardTransform t);
}
