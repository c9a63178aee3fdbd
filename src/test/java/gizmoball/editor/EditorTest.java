package gizmoball.editor;

import gizmoball.boardfile.BoardContents;
import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import org.junit.jupiter.api.BeforeEach;
import physics.Vect;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import java.awt.event.KeyEvent;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

class EditorTest extends EditorFixture {
    private int edits;

    @BeforeEach
    void setUp() {
        editor.addEditListener(() -> edits++);
    }

    /** Clicks the middle of a cell with the given tool. */
    private void click(Tool tool, int cx, int cy) {
        editor.setTool(tool);
        clickCell(cx, cy);
    }

    private void clickCell(int cx, int cy) {
        editor.press(cx + 0.5, cy + 0.5);
        editor.release(cx + 0.5, cy + 0.5);
    }

    private void drag(double x0, double y0, double x1, double y1) {
        editor.press(x0, y0);
        editor.drag((x0 + x1) / 2, (y0 + y1) / 2);
        editor.release(x1, y1);
    }

    @ParameterizedTest(name = "{0} placed at ({2},{3}) is named {1}")
    @CsvSource({
            "SQUARE, S1, 3, 4, SQUARE, 1, 1",
            "CIRCLE, C1, 0, 0, CIRCLE, 1, 1",
            "TRIANGLE, T1, 19, 19, TRIANGLE, 1, 1",
            "LEFT_FLIPPER, LF1, 5, 10, LEFT_FLIPPER, 2, 2",
            "RIGHT_FLIPPER, RF1, 18, 18, RIGHT_FLIPPER, 2, 2"})
    void clickingPlacesEachGizmoKindWithAGeneratedName(Tool tool, String name, int x, int y, GizmoKind kind,
                                                       int width, int height) {
        click(tool, x, y);

        Gizmo g = gizmo(name);
        assertThat(g.kind()).isEqualTo(kind);
        assertThat(List.of(g.x(), g.y(), g.width(), g.height())).containsExactly(x, y, width, height);
        assertThat(editor.selected()).contains(name);
        assertThat(edits).isEqualTo(1);
    }

    @Test
    void absorberIsTheRectangleDraggedOutInEitherDirection() {
        editor.setTool(Tool.ABSORBER);
        drag(2.5, 18.5, 7.5, 19.5);
        drag(19.9, 16.9, 12.1, 15.1);

        Gizmo a1 = gizmo("A1");
        assertThat(List.of(a1.x(), a1.y(), a1.width(), a1.height())).containsExactly(2, 18, 6, 2);
        Gizmo a2 = gizmo("A2");
        assertThat(List.of(a2.x(), a2.y(), a2.width(), a2.height())).containsExactly(12, 15, 8, 2);
    }

    @Test
    void ballIsPlacedAtTheSnappedClickAndTheDragGivesItsVelocity() {
        editor.setTool(Tool.BALL);
        // Press 5.1 snaps the centre to the quarter-cell 5.0; the drag from the press, (+1.2, -0.9) L, is
        // (12, -9) L/s at 10 L/s per L.
        drag(5.1, 5.1, 6.3, 4.2);

        BallView b = board.ball("B1").orElseThrow();
        assertThat(b.position().x()).isEqualTo(5.0);
        assertThat(b.position().y()).isEqualTo(5.0);
        assertThat(b.velocity().x()).isCloseTo(12, within(1e-9));
        assertThat(b.velocity().y()).isCloseTo(-9, within(1e-9));
        assertThat(editor.selected()).contains("B1");
    }

    @Test
    void aClickWithTheBallToolPlacesABallAtRestEvenOffTheSnapPoints() {
        editor.setTool(Tool.BALL);
        drag(7.37, 7.62, 7.4, 7.6);
        BallView b = board.ball("B1").orElseThrow();
        assertThat(List.of(b.position().x(), b.position().y())).containsExactly(7.25, 7.5);
        assertThat(List.of(b.velocity().x(), b.velocity().y())).containsExactly(0.0, 0.0);
    }

    @Test
    void draggingAGizmoMovesItKeepingTheCellThatWasGrabbed() {
        click(Tool.LEFT_FLIPPER, 4, 4);
        editor.setTool(Tool.SELECT);
        // Grabbed by its lower-right cell (5,5); released over (10,12): the box's top-left goes to (9,11).
        drag(5.5, 5.5, 10.5, 12.5);

        Gizmo lf = gizmo("LF1");
        assertThat(List.of(lf.x(), lf.y())).containsExactly(9, 11);
        assertThat(edits).isEqualTo(2);
    }

    @Test
    void draggingOntoAnotherGizmoIsRefusedAndLeavesBothInPlace() {
        click(Tool.SQUARE, 3, 3);
        click(Tool.CIRCLE, 6, 3);
        BoardContents before = BoardContents.of(board);
        editor.setTool(Tool.SELECT);
        drag(3.5, 3.5, 6.5, 3.5);

        assertThat(BoardContents.of(board)).isEqualTo(before);
        assertThat(lastMessage()).contains("overlap");
    }

    @Test
    void draggingABallMovesItsCentreByTheDragSnappedToQuarterCells() {
        board.addBall("B1", 3.0, 3.0, 1, 2);
        editor.setTool(Tool.SELECT);
        drag(3.1, 2.9, 8.2, 10.9);

        BallView b = board.ball("B1").orElseThrow();
        // 3.0 + (8.2 - 3.1) = 8.1 -> 8.0;  3.0 + (10.9 - 2.9) = 11.0
        assertThat(b.position().x()).isCloseTo(8.0, within(1e-9));
        assertThat(b.position().y()).isCloseTo(11.0, within(1e-9));
        assertThat(b.velocity().y()).isCloseTo(2, within(1e-9));
    }

    @Test
    void clickingABallWithoutDraggingOnlySelectsIt() {
        board.addBall("Ball", 3.1, 3.3, 0, 0);
        editor.setTool(Tool.SELECT);
        drag(3.1, 3.3, 3.12, 3.31);

        assertThat(board.ball("Ball").orElseThrow().position().x()).isEqualTo(3.1);
        assertThat(editor.selected()).contains("Ball");
        assertThat(edits).isZero();
    }

    @Test
    void rotateTurnsAGizmoAQuarterClockwiseEachClick() {
        click(Tool.TRIANGLE, 7, 7);
        editor.setTool(Tool.ROTATE);
        clickCell(7, 7);
        assertThat(gizmo("T1").rotation()).isEqualTo(1);
        clickCell(7, 7);
        clickCell(7, 7);
        clickCell(7, 7);
        assertThat(gizmo("T1").rotation()).isZero();
    }

    @Test
    void rotatingAFlipperByClickingItsLowerCellWorks() {
        click(Tool.RIGHT_FLIPPER, 10, 10);
        editor.setTool(Tool.ROTATE);
        clickCell(11, 11);
        assertThat(gizmo("RF1").rotation()).isEqualTo(1);
    }

    @Test
    void deleteRemovesTheGizmoWithItsConnectionsAndBindings() {
        click(Tool.SQUARE, 1, 1);
        click(Tool.LEFT_FLIPPER, 4, 4);
        board.connect(TriggerSource.gizmo("S1"), "LF1");
        board.bindKey(KeyEvent.VK_SPACE, KeyEdge.DOWN, "LF1");

        click(Tool.DELETE, 5, 5);

        assertThat(board.gizmo("LF1")).isEmpty();
        assertThat(board.connections()).isEmpty();
        assertThat(board.keyBindings()).isEmpty();
        assertThat(board.gizmo("S1")).isPresent();
    }

    @Test
    void deleteTakesABallBeforeTheAbsorberHoldingIt() {
        editor.setTool(Tool.ABSORBER);
        drag(0.5, 19.5, 19.5, 19.5);
        board.addBall("B1", 19.75, 19.75, 0, 0);

        editor.setTool(Tool.DELETE);
        editor.press(19.7, 19.7);

        assertThat(board.balls()).isEmpty();
        assertThat(board.gizmo("A1")).isPresent();
    }

    @Test
    void deleteOnAnEmptyCellSaysSo() {
        click(Tool.DELETE, 9, 9);
        assertThat(lastMessage()).isEqualTo("Nothing here to delete");
        assertThat(edits).isZero();
    }

    @Test
    void connectJoinsTheFirstClickedSourceToTheSecondClickedTarget() {
        click(Tool.CIRCLE, 2, 2);
        click(Tool.LEFT_FLIPPER, 8, 8);
        editor.setTool(Tool.CONNECT);
        clickCell(2, 2);
        assertThat(editor.connectSource()).contains(TriggerSource.gizmo("C1"));
        clickCell(9, 9);
        assertThat(board.connections()).as("not before the popup's answer").isEmpty();
        assertThat(editor.links().awaitedTargetKind()).contains(GizmoKind.LEFT_FLIPPER);
        editor.links().chooseConnection();

        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.gizmo("C1"), "LF1"));
        assertThat(editor.connectSource()).isEmpty();
        assertThat(editor.selected()).contains("C1");
    }

    @ParameterizedTest(name = "a click at ({0},{1}) picks the outer walls")
    @CsvSource({"-1, 5", "5, -0.5", "20.5, 20.5", "19.9, 10.5", "10.5, 0.1"})
    void connectTakesTheOuterWallsAsSourceOutsideOrOnTheBorder(double x, double y) {
        click(Tool.ABSORBER, 10, 18);
        editor.setTool(Tool.CONNECT);
        editor.press(x, y);
        clickCell(10, 18);
        editor.links().chooseConnection();

        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.OUTER_WALLS, "A1"));
    }

    @Test
    void aGizmoInABorderCellIsTheGizmoNotTheWalls() {
        click(Tool.SQUARE, 0, 5);
        click(Tool.SQUARE, 3, 5);
        editor.setTool(Tool.CONNECT);
        editor.press(0.1, 5.5);
        clickCell(3, 5);
        editor.links().chooseConnection();
        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.gizmo("S1"), "S2"));
    }

    @Test
    void theOuterWallsCannotBeATarget() {
        click(Tool.SQUARE, 3, 3);
        editor.setTool(Tool.CONNECT);
        clickCell(3, 3);
        editor.press(-2, 4);

        assertThat(board.connections()).isEmpty();
        assertThat(lastMessage()).contains("outer walls can only be a trigger source");
        assertThat(editor.connectSource()).contains(TriggerSource.gizmo("S1"));
    }

    @Test
    void aRefusedConnectionReportsTheBoardsReason() {
        click(Tool.SQUARE, 3, 3);
        click(Tool.SQUARE, 5, 3);
        editor.setTool(Tool.CONNECT);
        clickCell(3, 3);
        clickCell(5, 3);
        editor.links().chooseConnection();
        clickCell(3, 3);
        clickCell(5, 3);
        editor.links().chooseConnection();

        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.gizmo("S1"), "S2"));
        assertThat(messages).anyMatch(m -> m.startsWith("Connected"));
        assertThat(lastMessage()).doesNotStartWith("Connected");
        assertThat(edits).isEqualTo(3);
    }

    @Test
    void disconnectRemovesTheClickedConnection() {
        click(Tool.SQUARE, 3, 3);
        click(Tool.SQUARE, 5, 3);
        board.connect(TriggerSource.gizmo("S1"), "S2");
        board.connect(TriggerSource.gizmo("S2"), "S1");
        editor.setTool(Tool.DISCONNECT);
        clickCell(3, 3);
        clickCell(5, 3);

        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.gizmo("S2"), "S1"));
    }

    @Test
    void keyConnectBindsAKeyThatThenSwingsTheFlipperInPlay() {
        click(Tool.LEFT_FLIPPER, 4, 16);
        editor.setTool(Tool.KEY_CONNECT);
        clickCell(4, 16);
        assertThat(editor.keyPressed(KeyEvent.VK_SPACE, false)).isTrue();
        assertThat(editor.awaitingEdge()).isTrue();
        editor.links().chooseEdge(KeyEdge.DOWN);

        assertThat(board.keyBindings()).containsExactly(new KeyBinding(KeyEvent.VK_SPACE, KeyEdge.DOWN, "LF1"));
        assertThat(editor.awaitingEdge()).isFalse();

        board.keyDown(KeyEvent.VK_SPACE);
        // 1080 deg/s for 0.1 s would be 108 degrees: the flipper has reached its 90-degree stop.
        board.tick(0.1);
        FlipperView lf = (FlipperView) gizmo("LF1");
        assertThat(lf.isActive()).isTrue();
        assertThat(lf.angleFromRest()).isCloseTo(90, within(1e-9));
    }

    @Test
    void keyConnectTakesLetterKeysThatOtherwiseChooseTools() {
        click(Tool.CIRCLE, 4, 4);
        editor.setTool(Tool.KEY_CONNECT);
        clickCell(4, 4);
        editor.keyPressed(KeyEvent.VK_S, false);
        editor.links().chooseEdge(KeyEdge.UP);

        assertThat(editor.tool()).isEqualTo(Tool.KEY_CONNECT);
        assertThat(board.keyBindings()).containsExactly(new KeyBinding(KeyEvent.VK_S, KeyEdge.UP, "C1"));
    }

    @Test
    void escapeCancelsAPendingKeyConnect() {
        click(Tool.CIRCLE, 4, 4);
        editor.setTool(Tool.KEY_CONNECT);
        clickCell(4, 4);
        editor.keyPressed(KeyEvent.VK_Z, false);
        editor.keyPressed(KeyEvent.VK_ESCAPE, false);

        assertThat(editor.links().chooseEdge(KeyEdge.DOWN)).isFalse();
        assertThat(board.keyBindings()).isEmpty();
    }

    @Test
    void keyDisconnectRemovesBothEdgesOfThePressedKeyOnly() {
        click(Tool.RIGHT_FLIPPER, 10, 16);
        board.bindKey(KeyEvent.VK_M, KeyEdge.DOWN, "RF1");
        board.bindKey(KeyEvent.VK_M, KeyEdge.UP, "RF1");
        board.bindKey(KeyEvent.VK_N, KeyEdge.DOWN, "RF1");

        editor.setTool(Tool.KEY_DISCONNECT);
        clickCell(11, 17);
        editor.keyPressed(KeyEvent.VK_M, false);

        assertThat(board.keyBindings()).containsExactly(new KeyBinding(KeyEvent.VK_N, KeyEdge.DOWN, "RF1"));
        editor.undo();
        assertThat(board.keyBindings()).hasSize(3);
    }

    @Test
    void aRefusedOverlapLeavesTheBoardUnchangedAndSaysWhy() {
        click(Tool.SQUARE, 3, 4);
        BoardContents before = BoardContents.of(board);
        click(Tool.LEFT_FLIPPER, 2, 3);

        assertThat(BoardContents.of(board)).isEqualTo(before);
        assertThat(lastMessage()).contains("overlap").contains("S1");
        assertThat(edits).isEqualTo(1);
        editor.undo();
        assertThat(board.gizmos()).isEmpty();
        assertThat(editor.history().canUndo()).isFalse();
    }

    @Test
    void aPlacementLeavingTheBoardIsRefusedWithTheReason() {
        click(Tool.LEFT_FLIPPER, 19, 5);
        assertThat(board.gizmos()).isEmpty();
        assertThat(lastMessage()).containsIgnoringCase("outside");
    }

    @Test
    void hoverPreviewsWhetherAPlacementFits() {
        click(Tool.SQUARE, 3, 3);
        editor.setTool(Tool.LEFT_FLIPPER);
        editor.hover(10.5, 10.5);
        assertThat(editor.preview()).get().isEqualTo(
                new Preview.Footprint(10, 10, 2, 2, Optional.empty()));

        messages.clear();
        editor.hover(2.5, 2.5);
        Preview refused = editor.preview().orElseThrow();
        assertThat(refused.fits()).isFalse();
        assertThat(refused.problem().orElseThrow()).contains("overlap");
        assertThat(messages).containsExactly(refused.problem().get());
        // Moving within the same refusal does not repeat the message.
        editor.hover(2.7, 2.2);
        assertThat(messages).hasSize(1);
    }

    @Test
    void undoAndRedoStepThroughEveryEdit() {
        click(Tool.SQUARE, 1, 1);
        click(Tool.CIRCLE, 2, 2);
        click(Tool.TRIANGLE, 3, 3);
        click(Tool.ROTATE, 3, 3);
        BoardContents all = BoardContents.of(board);

        assertThat(editor.undo()).isTrue();
        assertThat(gizmo("T1").rotation()).isZero();
        editor.undo();
        editor.undo();
        assertThat(board.gizmos()).extracting(Gizmo::name).containsExactly("S1");
        editor.redo();
        editor.redo();
        editor.redo();
        assertThat(BoardContents.of(board)).isEqualTo(all);
        assertThat(editor.redo()).isFalse();
        assertThat(lastMessage()).isEqualTo("Nothing to redo");
    }

    @Test
    void aNewEditAfterUndoDropsTheRedoSteps() {
        click(Tool.SQUARE, 1, 1);
        click(Tool.SQUARE, 2, 2);
        editor.undo();
        assertThat(lastMessage()).isEqualTo("Undone: Placed S2 at (2,2)");
        click(Tool.CIRCLE, 5, 5);

        assertThat(editor.history().canRedo()).isFalse();
        assertThat(board.gizmos()).extracting(Gizmo::name).containsExactly("S1", "C1");
    }

    @Test
    void generatedNamesSkipNamesInUseByGizmosOrBalls() {
        board.addGizmo(GizmoKind.SQUARE, "S1", 0, 0);
        board.addBall("S2", 5.5, 5.5, 0, 0);
        click(Tool.SQUARE, 1, 0);
        assertThat(gizmo("S3").x()).isEqualTo(1);

        click(Tool.DELETE, 0, 0);
        click(Tool.SQUARE, 2, 0);
        assertThat(gizmo("S1").x()).isEqualTo(2);
    }

    @Test
    void constantsAreValidatedAndSetAsOneUndoStep() {
        assertThat(editor.properties().setConstants(12.5, 0.5, -1)).isFalse();
        assertThat(board.gravity()).isEqualTo(Board.DEFAULT_GRAVITY);
        assertThat(board.mu()).isEqualTo(Board.DEFAULT_MU);

        assertThat(editor.properties().setConstants(12.5, 0.5, 0.1)).isTrue();
        assertThat(List.of(board.gravity(), board.mu(), board.mu2())).containsExactly(12.5, 0.5, 0.1);
        editor.undo();
        assertThat(List.of(board.gravity(), board.mu(), board.mu2()))
                .containsExactly(Board.DEFAULT_GRAVITY, Board.DEFAULT_MU, Board.DEFAULT_MU2);
        assertThat(editor.history().canUndo()).isFalse();
    }

    @Test
    void theSelectedBallsPositionAndVelocityCanBeTypedIn() {
        board.addBall("B1", 3, 3, 0, 0);
        assertThat(editor.properties().setBall("B1", 4.5, 6, -3, 7.25)).isTrue();
        BallView b = board.ball("B1").orElseThrow();
        assertThat(List.of(b.position().x(), b.position().y(), b.velocity().x(), b.velocity().y()))
                .containsExactly(4.5, 6.0, -3.0, 7.25);

        BoardContents before = BoardContents.of(board);
        assertThat(editor.properties().setBall("B1", 25, 6, 1, 1)).isFalse();
        assertThat(BoardContents.of(board)).isEqualTo(before);
        editor.undo();
        // One step took back both the move and the new velocity.
        assertThat(board.ball("B1").orElseThrow().position()).isEqualTo(new Vect(3, 3));
        assertThat(board.ball("B1").orElseThrow().velocity()).isEqualTo(Vect.ZERO);
    }

    /** Issue 14: a velocity change used to delete and re-add the ball, so B1, B2 were saved as B2, B1. */
    @Test
    void changingABallsVelocityKeepsTheOrderOfTheBalls() {
        board.addBall("B1", 3, 3, 0, 0);
        board.addBall("B2", 6, 6, 0, 0);
        assertThat(editor.properties().setBall("B1", 3, 3, 5, -5)).isTrue();
        assertThat(board.balls()).extracting(BallView::name).containsExactly("B1", "B2");
        assertThat(board.ball("B1").orElseThrow().velocity()).isEqualTo(new Vect(5, -5));
    }

    /** Issue 12 item 12: hovering and clicking word a refusal the same way, naming no gizmo that is not there. */
    @Test
    void aRefusedPlacementIsWordedAlikeOnHoverAndOnClick() {
        board.addGizmo(GizmoKind.SQUARE, "S1", 2, 4);
        editor.setTool(Tool.SQUARE);
        editor.hover(2.5, 4.5);
        String onHover = lastMessage();
        assertThat(onHover).startsWith("a square at (2,4) would overlap").contains("S1");
        editor.press(2.5, 4.5);
        editor.release(2.5, 4.5);
        assertThat(lastMessage()).isEqualTo(onHover);
        assertThat(messages).noneMatch(m -> m.contains("S2"));
        assertThat(board.gizmos()).hasSize(1);
    }

    /** The preview names the kind with its article, as every message does: an absorber, not "a absorber". */
    @Test
    void aRefusedAbsorberIsNamedWithItsArticle() {
        board.addGizmo(GizmoKind.SQUARE, "S1", 4, 18);
        editor.setTool(Tool.ABSORBER);
        drag(2.5, 18.5, 7.5, 19.5);
        assertThat(lastMessage()).startsWith("an absorber at (2,18) would overlap gizmo S1");
        assertThat(board.gizmos()).hasSize(1);
    }

    /** Issue 12 item 11: a circle and an absorber look the same turned. */
    @Test
    void rotatingACircleOrAnAbsorberIsRefusedWithoutAnUndoStep() {
        board.addGizmo(GizmoKind.CIRCLE, "C1", 2, 2);
        board.addAbsorber("A", 0, 18, 20, 20);
        Optional<String> lastStep = editor.history().undoable();
        click(Tool.ROTATE, 2, 2);
        assertThat(lastMessage()).isEqualTo("C1 is a circle: it looks the same turned, so it cannot be rotated");
        editor.select("A");
        assertThat(editor.rotateSelected()).isFalse();
        assertThat(lastMessage()).isEqualTo("A is an absorber: it looks the same turned, so it cannot be rotated");
        assertThat(board.gizmo("C1").orElseThrow().rotation()).isZero();
        assertThat(editor.history().undoable()).isEqualTo(lastStep);
        assertThat(edits).isZero();
    }

    @Test
    void clearBoardEmptiesItAndUndoBringsItBack() {
        click(Tool.SQUARE, 1, 1);
        click(Tool.LEFT_FLIPPER, 4, 4);
        board.connect(TriggerSource.gizmo("S1"), "LF1");
        editor.properties().setConstants(10, 0, 0);
        BoardContents full = BoardContents.of(board);

        editor.clearBoard();
        assertThat(board.gizmos()).isEmpty();
        assertThat(board.connections()).isEmpty();
        assertThat(board.gravity()).isEqualTo(Board.DEFAULT_GRAVITY);
        editor.undo();
        assertThat(BoardContents.of(board)).isEqualTo(full);
    }

    @Test
    void toolShortcutsSwitchToolsButNotWithCtrl() {
        assertThat(editor.keyPressed(KeyEvent.VK_T, false)).isTrue();
        assertThat(editor.tool()).isEqualTo(Tool.TRIANGLE);
        assertThat(editor.keyPressed(KeyEvent.VK_S, true)).isFalse();
        assertThat(editor.tool()).isEqualTo(Tool.TRIANGLE);
        assertThat(editor.keyPressed(KeyEvent.VK_F12, false)).isFalse();
    }

    @Test
    void everyToolHasItsOwnShortcut() {
        assertThat(Arrays.stream(Tool.values()).map(Tool::shortcut).distinct())
                .hasSize(Tool.values().length);
    }

    @Test
    void theDeleteKeyDeletesTheSelection() {
        click(Tool.SQUARE, 6, 6);
        editor.setTool(Tool.SELECT);
        clickCell(6, 6);
        editor.keyPressed(KeyEvent.VK_DELETE, false);
        assertThat(board.gizmos()).isEmpty();
        assertThat(editor.selected()).isEmpty();
    }

    @Test
    void selectingOutsideTheBoardSelectsTheOuterWalls() {
        editor.setTool(Tool.SELECT);
        editor.press(-1, 10);
        editor.release(-1, 10);
        assertThat(editor.selected()).contains(TriggerSource.OuterWalls.NAME);
        assertThat(editor.deleteSelected()).isFalse();
    }

    @Test
    void theTargetUnderThePointerDependsOnTheTool() {
        click(Tool.SQUARE, 4, 4);
        board.addBall("B1", 8.5, 8.5, 0, 0);
        editor.setTool(Tool.ROTATE);
        editor.hover(4.5, 4.5);
        assertThat(editor.target()).contains("S1");
        editor.hover(8.5, 8.6);
        assertThat(editor.target()).isEmpty();

        editor.setTool(Tool.DELETE);
        editor.hover(8.5, 8.6);
        assertThat(editor.target()).contains("B1");

        editor.setTool(Tool.CONNECT);
        editor.hover(-1, 3);
        assertThat(editor.target()).contains(TriggerSource.OuterWalls.NAME);

        editor.setTool(Tool.SQUARE);
        editor.hover(4.5, 4.5);
        assertThat(editor.target()).isEmpty();
        editor.exit();
        assertThat(editor.pointer()).isEmpty();
    }

    @Test
    void keyConnectSaysWhichGizmoWaitsForAKey() {
        click(Tool.TRIANGLE, 4, 4);
        editor.setTool(Tool.KEY_CONNECT);
        assertThat(editor.awaitingKeyFor()).isEmpty();
        clickCell(4, 4);
        assertThat(editor.awaitingKeyFor()).contains("T1");
        editor.keyPressed(KeyEvent.VK_Q, false);
        assertThat(editor.awaitingKeyFor()).isEmpty();
        assertThat(editor.awaitingEdge()).isTrue();
    }

    @Test
    void arrowKeysNudgeTheSelectionByACellOrAQuarterCellAndStopAtTheEdge() {
        click(Tool.SQUARE, 0, 3);
        editor.keyPressed(KeyEvent.VK_RIGHT, false);
        editor.keyPressed(KeyEvent.VK_DOWN, false);
        assertThat(List.of(gizmo("S1").x(), gizmo("S1").y())).containsExactly(1, 4);
        editor.keyPressed(KeyEvent.VK_LEFT, false);
        editor.keyPressed(KeyEvent.VK_LEFT, false);
        assertThat(gizmo("S1").x()).isZero();
        assertThat(lastMessage()).containsIgnoringCase("outside");

        board.addBall("B1", 5, 5, 0, 0);
        editor.select("B1");
        editor.keyPressed(KeyEvent.VK_UP, false);
        assertThat(board.ball("B1").orElseThrow().position().y()).isEqualTo(4.75);
    }

    @Test
    void ctrlCombinationsAreNotTakenAsTheKeyToBind() {
        click(Tool.CIRCLE, 4, 4);
        editor.setTool(Tool.KEY_CONNECT);
        clickCell(4, 4);
        assertThat(editor.keyPressed(KeyEvent.VK_Z, true)).isFalse();
        assertThat(editor.awaitingKeyFor()).contains("C1");
    }

    @Test
    void theArrowKeysAnswerDownOrUpAndOtherKeysWaitMeanwhile() {
        click(Tool.RIGHT_FLIPPER, 12, 16);
        editor.setTool(Tool.KEY_CONNECT);
        clickCell(12, 16);
        editor.keyPressed(KeyEvent.VK_SLASH, false);
        assertThat(editor.keyPressed(KeyEvent.VK_S, false)).isTrue();
        assertThat(editor.tool()).isEqualTo(Tool.KEY_CONNECT);
        editor.keyPressed(KeyEvent.VK_UP, false);

        assertThat(board.keyBindings()).containsExactly(new KeyBinding(KeyEvent.VK_SLASH, KeyEdge.UP, "RF1"));
        assertThat(editor.awaitingEdge()).isFalse();
    }

    @Test
    void aColourTypedAsHexIsOneUndoableEditAndBadTextIsRefusedWithAReason() {
        board.addGizmo(GizmoKind.CIRCLE, "C", 4, 4);
        assertThat(editor.properties().setColour("C", " 99b3ff ")).isTrue();
        assertThat(gizmo("C").colour()).contains(new Rgb(0x99, 0xb3, 0xff));
        assertThat(lastMessage()).isEqualTo("C coloured #99b3ff");
        int before = edits;
        assertThat(editor.properties().setColour("C", "#99B3FF")).as("the same colour").isTrue();
        assertThat(edits).as("is no edit").isEqualTo(before);
        assertThat(editor.properties().setColour("C", "#12345")).isFalse();
        assertThat(lastMessage()).contains("'#12345' is not #rrggbb");
        assertThat(editor.properties().setColour("Nope", "#123456")).isFalse();
        assertThat(editor.properties().setColour("C", "")).isTrue();
        assertThat(gizmo("C").colour()).isEmpty();
        editor.undo();
        assertThat(gizmo("C").colour()).contains(new Rgb(0x99, 0xb3, 0xff));
        editor.undo();
        assertThat(gizmo("C").colour()).isEmpty();
        assertThat(PropertyEdits.hex(new Rgb(0, 10, 255))).isEqualTo("#000aff");
    }

    @Test
    void aBallIsNeverPlacedOnAnotherEvenWhereAFileLoadedBallsOnEachOther() {
        board.addBall("A", 5.1, 5.1, 0, 0);
        board.addBallOverlappingBalls("A2", 5.2, 5.1, 0, 0);   // as the loader places balls a file put on each other
        editor.setTool(Tool.BALL);
        // Snapped to (5.5, 5.0): 0.41 L from A's centre, less than the two radii.
        drag(5.6, 4.9, 5.6, 4.9);
        assertThat(board.balls()).extracting(BallView::name).containsExactly("A", "A2");
        assertThat(lastMessage()).contains("would overlap ball A");
    }

    /** Issue 23, item 16: the editor's messages write a connection with the arrow the panels use. */
    @Test
    void connectMakesTheConnectionWithTheOrderChosenInThePopup() {
        click(Tool.SQUARE, 3, 3);
        click(Tool.LEFT_FLIPPER, 8, 8);
        editor.setTool(Tool.CONNECT);
        clickCell(3, 3);
        clickCell(8, 8);
        editor.links().orderPending(Order.of(Action.RAISE).after(0.25));
        editor.links().chooseConnection();

        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.gizmo("S1"), "LF1",
                Order.of(Action.RAISE).after(0.25)));
        assertThat(lastMessage()).isEqualTo("Connected S1 \u2192 LF1 raise after 0.25");
    }

    @Test
    void connectionsAreWrittenWithOneArrowInMessages() {
        click(Tool.SQUARE, 3, 3);
        click(Tool.SQUARE, 5, 3);
        editor.setTool(Tool.CONNECT);
        clickCell(3, 3);
        clickCell(5, 3);
        editor.links().chooseConnection();
        assertThat(messages).contains("Connected S1 \u2192 S2");

        editor.properties().disconnect(TriggerSource.gizmo("S1"), "S2");
        assertThat(lastMessage()).isEqualTo("Disconnected S1 \u2192 S2");
        assertThat(messages).noneMatch(m -> m.contains("->"));
    }

    /** Issue 23, item 15: a refusal is kept, for the field that asked, with its reason. */
    @Test
    void aRefusedEditLeavesItsReasonForTheFieldThatAskedForIt() {
        assertThat(editor.properties().setConstants(25, -1, 0.025)).isFalse();
        assertThat(editor.lastRefusal()).hasValueSatisfying(reason -> assertThat(lastMessage()).isEqualTo(reason));
        click(Tool.SQUARE, 3, 3);
        assertThat(editor.properties().setColour("S1", "green")).isFalse();
        assertThat(editor.lastRefusal()).contains(lastMessage());
    }
}
