package gizmoball.view;

import java.awt.event.KeyEvent;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.KeyStroke;

/**
 * Escape closes a dialog of the game's own, as it closes Swing's option panes and choosers: whatever has the focus
 * inside it, closing is the dialog's cancel (keep the board, leave the table).
 */
public final class EscapeCloses {
    private EscapeCloses() {
    }

    public static void install(JDialog dialog) {
        dialog.getRootPane().registerKeyboardAction(e -> dialog.dispose(), KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0),
                JComponent.WHEN_IN_FOCUSED_WINDOW);
    }
}
