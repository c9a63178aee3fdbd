package gizmoball.boardfile;

import gizmoball.model.gizmo.Setting;
import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;

import java.util.function.Consumer;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * What counts as the same design: the session marks a board unsaved, and the edit history takes a step, only where
 * {@link BoardContents} differ. A change of a kind's own number alone must show.
 */
class BoardContentsTest {

    private static Board withEveryTunedKind() {
        Board board = new Board();
        board.addGizmo(GizmoKind.ACCELERATOR, "A", 2, 2);
        board.addGizmo(GizmoKind.SPAWNER, "P", 5, 2);
        board.addGizmo(GizmoKind.SPINNER, "N", 8, 2);
        return board;
    }

    static Stream<Arguments> changes() {
        return Stream.of(
                Arguments.of("an accelerator's factor", (Consumer<Board>) b -> b.set("A", new Setting.Factor(2))),
                Arguments.of("a spawner's velocity", (Consumer<Board>) b -> b.set("P", new Setting.Launch(0, -30))),
                Arguments.of("a spinner's speed", (Consumer<Board>) b -> b.set("N", new Setting.Speed(-1))));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("changes")
    void aBoardWithOneKindsNumberChangedIsAnotherDesign(String what, Consumer<Board> change) {
        Board before = withEveryTunedKind();
        Board after = before.copy();

        change.accept(after);

        assertThat(BoardContents.sameDesign(before, after)).as(what).isFalse();
        assertThat(BoardContents.of(before).differences(BoardContents.of(after))).hasSize(1);
        assertThat(BoardContents.sameDesign(before, before.copy())).isTrue();
    }
}
