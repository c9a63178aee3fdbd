package gizmoball.view;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import java.awt.event.KeyEvent;
import java.util.List;
import org.junit.jupiter.api.Test;

class KeyHelpTest {
    @Test
    void oneLinePerKeyAndGizmoWithItsEdges() {
        List<KeyBinding> bindings = List.of(
                new KeyBinding(KeyEvent.VK_Z, KeyEdge.DOWN, "LF"),
                new KeyBinding(KeyEvent.VK_SPACE, KeyEdge.DOWN, "A"),
                new KeyBinding(KeyEvent.VK_Z, KeyEdge.UP, "LF"),
                new KeyBinding(KeyEvent.VK_Z, KeyEdge.DOWN, "RF"));

        assertThat(KeyHelp.describe(bindings)).containsExactly(
                KeyEvent.getKeyText(KeyEvent.VK_Z) + ": LF (down, up)",
                KeyEvent.getKeyText(KeyEvent.VK_SPACE) + ": A (down)",
                KeyEvent.getKeyText(KeyEvent.VK_Z) + ": RF (down)");
    }

    @Test
    void noBindingsNoLines() {
        assertThat(KeyHelp.describe(List.of())).isEmpty();
    }
}
