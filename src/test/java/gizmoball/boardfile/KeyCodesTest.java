package gizmoball.boardfile;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.event.KeyEvent;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class KeyCodesTest {

    @ParameterizedTest
    @ValueSource(ints = {KeyEvent.VK_SPACE, KeyEvent.VK_Z, KeyEvent.VK_SLASH, KeyEvent.VK_DELETE, KeyEvent.VK_ENTER,
            KeyEvent.VK_LEFT, KeyEvent.VK_F24, KeyEvent.VK_DEAD_GRAVE, KeyEvent.VK_0, KeyEvent.VK_NUMPAD9})
    void everyKeyEventConstantIsKnown(int keyCode) {
        assertThat(KeyCodes.isKnown(keyCode)).isTrue();
    }

    @ParameterizedTest
    @ValueSource(ints = {KeyEvent.VK_UNDEFINED, -1, 15, 1_000_000})
    void otherCodesAreNot(int keyCode) {
        assertThat(KeyCodes.isKnown(keyCode)).isFalse();
    }
}
