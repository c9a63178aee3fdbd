package gizmoball.editor;

import static org.assertj.core.api.Assertions.assertThat;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.game.GameRules;
import gizmoball.model.game.Nudge;
import gizmoball.model.game.Tilt;
import java.util.Optional;
import java.util.OptionalDouble;
import org.junit.jupiter.api.Test;

/** Build mode sets the nudge, the tilt and the ball save as one undo step, and refuses with the board's reasons. */
class TableSettingsTest {

    @Test
    void theNudgeTiltAndBallSaveAreOneEditThatUndoes() {
        Board board = new Board();
        Editor editor = Editor.of(board);

        assertThat(editor.properties().setTable(OptionalDouble.of(5), 3, 4, 2)).isTrue();
        assertThat(board.gameRules().nudge()).contains(new Nudge(5, 37, 39, 38));
        assertThat(board.gameRules().tilt()).isEqualTo(new Tilt(3, 4));
        assertThat(board.gameRules().ballSaveSeconds()).isEqualTo(2);

        editor.undo();
        assertThat(board.gameRules()).isEqualTo(GameRules.DEFAULT);
    }

    @Test
    void badValuesAndKeysTheBoardUsesAreRefused() {
        Board board = new Board();
        board.addAbsorber("A", 0, 19, 20, 20);
        board.bindKey(37, KeyEdge.DOWN, "A");
        Editor editor = Editor.of(board);

        assertThat(editor.properties().setTable(OptionalDouble.of(5), 1.5, 4, 0)).isFalse();
        assertThat(editor.lastRefusal()).hasValueSatisfying(r -> assertThat(r).contains("whole number of nudges"));
        assertThat(editor.properties().setTable(OptionalDouble.empty(), 4, 5, 40)).isFalse();
        assertThat(editor.lastRefusal()).hasValueSatisfying(r -> assertThat(r).contains("0 (none) to 30 seconds"));
        assertThat(editor.properties().setTable(OptionalDouble.of(4), 4, 5, 0)).isFalse();
        assertThat(editor.lastRefusal()).hasValueSatisfying(r -> assertThat(r).contains("a nudge key drives nothing"));
        assertThat(board.gameRules().nudge()).isEqualTo(Optional.empty());
    }
}
