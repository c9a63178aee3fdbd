package gizmoball.controller;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Save As's naming rule, without a window. */
class SaveAsNameTest {
    @Test
    void aNameWithoutExtensionGetsTxtUnderTheBoardFilesFilter() {
        assertThat(BoardFileCommands.withBoardExtension(Path.of("/b/my board"), true)).isEqualTo(Path.of("/b/my board.txt"));
    }

    @Test
    void aNameWithAnExtensionIsKept() {
        assertThat(BoardFileCommands.withBoardExtension(Path.of("/b/x.gizmo"), true)).isEqualTo(Path.of("/b/x.gizmo"));
        assertThat(BoardFileCommands.withBoardExtension(Path.of("/b/x.board"), true)).isEqualTo(Path.of("/b/x.board"));
    }

    @Test
    void aHiddenNameHasNoExtensionYet() {
        assertThat(BoardFileCommands.withBoardExtension(Path.of("/b/.pinball"), true)).isEqualTo(Path.of("/b/.pinball.txt"));
    }

    @Test
    void underAllFilesTheNameIsTakenAsTyped() {
        assertThat(BoardFileCommands.withBoardExtension(Path.of("/b/my board"), false)).isEqualTo(Path.of("/b/my board"));
    }
}
