package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import java.awt.event.KeyEvent;
import org.junit.jupiter.api.Test;

class KeyHelpTest {
    private static String key(int code) {
        return KeyEvent.getKeyText(code);
    }

    @Test
    void oneLinePerKeyAndGizmoNamingWhatTheGizmoIsAndHowTheKeyIsUsed() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 6, 16);
        board.addGizmo(GizmoKind.RIGHT_FLIPPER, "RF", 12, 16);
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addGizmo(GizmoKind.SQUARE, "S", 2, 2);
        board.bindKey(KeyEvent.VK_Z, KeyEdge.DOWN, "LF");
        board.bindKey(KeyEvent.VK_SPACE, KeyEdge.DOWN, "A");
        board.bindKey(KeyEvent.VK_Z, KeyEdge.UP, "LF");
        board.bindKey(KeyEvent.VK_Z, KeyEdge.DOWN, "RF");
        board.bindKey(KeyEvent.VK_X, KeyEdge.UP, "S");
        board.bindKey(KeyEvent.VK_Q, KeyEdge.DOWN, "S");
        board.bindKey(KeyEvent.VK_Q, KeyEdge.UP, "S");

        assertThat(KeyHelp.describe(board)).containsExactly(
                key(KeyEvent.VK_Z) + ": left flipper LF (hold)",
                key(KeyEvent.VK_SPACE) + ": absorber A (press)",
                key(KeyEvent.VK_Z) + ": right flipper RF (press)",
                key(KeyEvent.VK_X) + ": square S (release)",
                key(KeyEvent.VK_Q) + ": square S (press and release)");
    }

    @Test
    void noBindingsNoLines() {
        assertThat(KeyHelp.describe(new Board())).isEmpty();
    }
}
