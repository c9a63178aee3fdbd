package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Rgb;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;

import org.junit.jupiter.api.Test;

/** What the board offers for files of other implementations: gizmo colours, CHANGE keys, balls loaded overlapping. */
class BoardFileDialectSupportTest {

    @Test
    void rgbPacksItsChannelsAndIgnoresAlphaWhenUnpacking() {
        assertThat(new Rgb(0x12, 0x34, 0x56).packed()).isEqualTo(0x123456);
        assertThat(Rgb.of(0xff0000ff)).isEqualTo(new Rgb(0, 0, 255));   // Java's ARGB int of opaque blue
        assertThatThrownBy(() -> new Rgb(256, 0, 0)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new Rgb(0, -1, 0)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void aColourIsKeptPerGizmoCopiedWithTheBoardAndResetToTheKindsColour() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "S", 1, 1);
        board.addGizmo(GizmoKind.CIRCLE, "C", 3, 3);
        List<BoardChange> heard = new ArrayList<>();
        board.addObserver((b, change) -> heard.add(change));
        board.setColour("S", Optional.of(new Rgb(1, 2, 3)));
        assertThat(heard).containsExactly(BoardChange.EDIT);
        assertThat(board.gizmo("S").orElseThrow().colour()).contains(new Rgb(1, 2, 3));
        assertThat(board.gizmo("C").orElseThrow().colour()).isEmpty();
        Board copy = board.copy();
        board.setColour("S", Optional.empty());
        assertThat(board.gizmo("S").orElseThrow().colour()).isEmpty();
        assertThat(copy.gizmo("S").orElseThrow().colour()).contains(new Rgb(1, 2, 3));
        board.moveGizmo("C", 5, 5);
        board.setColour("C", Optional.of(new Rgb(9, 9, 9)));
        board.rotate("C");
        assertThat(board.gizmo("C").orElseThrow().colour()).contains(new Rgb(9, 9, 9));
        assertThatThrownBy(() -> board.setColour("X", Optional.of(new Rgb(0, 0, 0))))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("no gizmo named X");
    }

    @Test
    void aChangeKeyTogglesAFlipperOnEachPressAndFiresAnAbsorber() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "F", 2, 2);
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addBall("B", 4, 19.5, 0, 0);
        board.bindKey(70, KeyEdge.CHANGE, "F");
        board.bindKey(65, KeyEdge.CHANGE, "A");
        FlipperView flipper = (FlipperView) board.gizmo("F").orElseThrow();
        board.keyDown(70);
        assertThat(flipper.isActive()).isTrue();
        board.keyUp(70);   // a release does nothing: the press was the trigger
        assertThat(flipper.isActive()).isTrue();
        board.keyDown(70);
        assertThat(flipper.isActive()).isFalse();
        board.keyUp(65);
        assertThat(board.ball("B").orElseThrow().isCaptured()).isTrue();
        board.keyDown(65);
        assertThat(board.ball("B").orElseThrow().isCaptured()).isFalse();
    }

    @Test
    void aBallMayBeAddedOnOtherBallsButOnNoGizmoAndSaysWhichBallsItOverlaps() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "S", 10, 10);
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addBall("B1", 5, 5, 0, 0);
        board.addBall("B2", 5.5, 5, 0, 0);   // touching B1: allowed everywhere
        assertThatThrownBy(() -> board.addBall("B3", 5.2, 5, 0, 0)).isInstanceOf(BoardEditException.class)
                .hasMessageContaining("would overlap ball B1");
        assertThat(board.addBallOverlappingBalls("B3", 5.2, 5, 1, 0)).containsExactly("B1", "B2");
        assertThat(board.ball("B3").orElseThrow().velocity().x()).isEqualTo(1);
        assertThat(board.addBallOverlappingBalls("B4", 6.0, 5, 0, 0)).isEmpty();   // touching B2 is no overlap
        assertThat(board.addBallOverlappingBalls("B5", 3, 19.5, 0, 0)).isEmpty();  // captured
        assertThatThrownBy(() -> board.addBallOverlappingBalls("B6", 10.5, 10.5, 0, 0))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("would overlap gizmo S");
        assertThatThrownBy(() -> board.addBallOverlappingBalls("B1", 15, 5, 0, 0))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("already used");
        assertThatThrownBy(() -> board.moveBall("B4", 5.1, 5)).isInstanceOf(BoardEditException.class)
                .hasMessageContaining("would overlap ball");
    }

    @Test
    void theInvariantsExemptOnlyThePairsSaidToBePassingThrough() {
        Board board = new Board();
        board.addBall("B1", 5, 5, 0, 0);
        board.addBallOverlappingBalls("B2", 5.2, 5, 0, 0);
        board.addBallOverlappingBalls("B3", 5.1, 5.1, 0, 0);
        assertThat(Invariants.violations(board)).hasSize(3);
        assertThat(Invariants.violations(board, Set.of(Set.of("B1", "B2"), Set.of("B2", "B3"))))
                .singleElement().asString().contains("B1").contains("B3");
    }
}
