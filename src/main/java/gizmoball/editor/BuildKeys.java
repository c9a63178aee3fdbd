package gizmoball.editor;

import java.awt.event.KeyEvent;
import java.util.Optional;

/**
 * The keys of build mode over the board. A step waiting for a key (Key Connect, Key Disconnect) takes any key but
 * Escape (which cancels) and Ctrl/Alt/Meta combinations (which belong to the menus, e.g. Ctrl+Z while waiting).
 * Otherwise Delete removes the selection, the arrow keys nudge it and the tool shortcuts switch tools.
 */
final class BuildKeys {
    private BuildKeys() {
    }

    /** Whether the key was used. */
    static boolean pressed(Editor editor, int keyCode, boolean commandModifier) {
        if (keyCode == KeyEvent.VK_ESCAPE) {
            editor.cancel();
            editor.say("Cancelled");
            return true;
        }
        if (commandModifier) {
            return false;
        }
        if (editor.keyToTool(keyCode)) {
            return true;
        }
        switch (keyCode) {
            case KeyEvent.VK_DELETE, KeyEvent.VK_BACK_SPACE -> editor.deleteSelected();
            case KeyEvent.VK_LEFT -> editor.nudgeSelected(-1, 0);
            case KeyEvent.VK_RIGHT -> editor.nudgeSelected(1, 0);
            case KeyEvent.VK_UP -> editor.nudgeSelected(0, -1);
            case KeyEvent.VK_DOWN -> editor.nudgeSelected(0, 1);
            default -> {
                Optional<Tool> shortcut = Tool.forShortcut(keyCode);
                shortcut.ifPresent(editor::setTool);
                return shortcut.isPresent();
            }
        }
        return true;
    }
}
