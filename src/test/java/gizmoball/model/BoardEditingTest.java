package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import gizmoball.model.gizmo.BumperView;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import physics.Vect;

class BoardEditingTest {

    /** A small board with one of everything, a connection and a key binding. */
    static Board sample() {
        Board board = new Board();
        board.addGizmo(GizmoKind.SQUARE, "S1", 2, 3);
        board.addGizmo(GizmoKind.CIRCLE, "C1", 5, 5);
        board.addGizmo(GizmoKind.TRIANGLE, "T1", 7, 2);
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "LF", 10, 10);
        board.addGizmo(GizmoKind.RIGHT_FLIPPER, "RF", 14, 10);
        board.addAbsorber("A", 0, 18, 20, 20);
        board.addBall("B1", 1.5, 1.5, 3, -4);
        board.addBall("B2", 19.5, 19.5, 0, 0);
        board.connect(TriggerSource.gizmo("S1"), "LF");
        board.connect(TriggerSource.OUTER_WALLS, "RF");
        board.bindKey(32, KeyEdge.DOWN, "LF");
        return board;
    }

    @Test
    void addedGizmosAreFoundByNameAndByEveryCellOfTheirFootprint() {
        Board board = sample();
        assertThat(board.gizmos()).extracting(Gizmo::name).containsExactly("S1", "C1", "T1", "LF", "RF", "A");
        assertThat(board.gizmoAt(10, 10)).map(Gizmo::name).contains("LF");
        assertThat(board.gizmoAt(11, 11)).map(Gizmo::name).contains("LF");
        assertThat(board.gizmoAt(12, 10)).isEmpty();
        assertThat(board.gizmoAt(19, 19)).map(Gizmo::name).contains("A");
        assertThat(board.gizmoAt(-1, 0)).isEmpty();
        Gizmo absorber = board.gizmo("A").orElseThrow();
        assertThat(List.of(absorber.x(), absorber.y(), absorber.width(), absorber.height())).containsExactly(0, 18, 20, 2);
        assertThat(board.gizmo("S1").orElseThrow().reflectionCoefficient()).isEqualTo(1.0);
        assertThat(board.gizmo("LF").orElseThrow().reflectionCoefficient()).isEqualTo(0.95);
        assertThat(absorber.reflectionCoefficient()).isZero();
        assertThat(board.gizmo("S1").orElseThrow().lastTriggeredAt()).isEqualTo(Double.NEGATIVE_INFINITY);
    }

    @Test
    void aBallPlacedOnAnAbsorberIsCapturedAtItsBottomRightCorner() {
        Board board = sample();
        BallView ball = board.ball("B2").orElseThrow();
        assertThat(ball.isCaptured()).isTrue();
        assertThat(ball.position()).isEqualTo(new Vect(20 - 0.25, 20 - 0.25));
        assertThat(ball.velocity()).isEqualTo(Vect.ZERO);
        assertThat(board.ball("B1").orElseThrow().isCaptured()).isFalse();
        assertThat(ballsCovering(board, 1.6, 1.4)).containsExactly("B1");
        assertThat(ballsCovering(board, 1.9, 1.9)).isEmpty();
    }

    /**
     * A ball resting on the floor in play can lie 4e-15 L into it (19.750000000000004); saved then, it must load
     * again, as a ball touching a gizmo to rounding does. The walls refuse only what a gizmo refuses: more than
     * {@code Tolerances.PLACEMENT} (1e-8 L) inside.
     */
    @Test
    void aBallOnAWallToRoundingIsPlacedAndOneDeeperThanThePlacementToleranceIsRefused() {
        Board board = new Board();
        board.addBall("Floor", 10, 19.750000000000004, 0, 0);
        board.addBall("Ceiling", 12, 0.2499999999999994, 0, 0);
        board.addBall("Left", 0.25 - 5e-9, 10, 0, 0);
        board.addBall("Right", 19.75 + 5e-9, 12, 0, 0);
        assertThat(board.balls()).hasSize(4);
        assertThatThrownBy(() -> board.addBall("Deeper", 5, 19.75 + 2e-8, 0, 0))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("outside the board");
        assertThatThrownBy(() -> board.addBall("Beyond", 0.25 - 2e-8, 5, 0, 0))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("outside the board");
    }

    @Test
    void aBallFasterThanTheLimitIsClampedToIt() {
        Board board = new Board();
        board.addBall("B", 10, 10, 300, 400);
        Vect v = board.ball("B").orElseThrow().velocity();
        assertThat(v.length()).isCloseTo(Board.MAX_SPEED, org.assertj.core.api.Assertions.within(1e-9));
        assertThat(v.x() / v.y()).isCloseTo(0.75, org.assertj.core.api.Assertions.within(1e-12));
    }

    @Test
    void triangleCornersTurnClockwiseAboutTheCellCentre() {
        Board board = new Board();
        board.addGizmo(GizmoKind.TRIANGLE, "T", 3, 4);
        BumperView triangle = (BumperView) board.gizmo("T").orElseThrow();
        assertThat(triangle.outline()).containsExactly(new Vect(3, 4), new Vect(4, 4), new Vect(3, 5));
        board.rotate("T");
        assertThat(triangle.rotation()).isEqualTo(1);
        assertThat(triangle.outline()).containsExactly(new Vect(4, 4), new Vect(4, 5), new Vect(3, 4));
        board.rotate("T");
        board.rotate("T");
        board.rotate("T");
        assertThat(triangle.rotation()).isZero();
        assertThat(triangle.outline()).containsExactly(new Vect(3, 4), new Vect(4, 4), new Vect(3, 5));
    }

    @Test
    void squareOutlineAndCircleShape() {
        Board board = sample();
        BumperView square = (BumperView) board.gizmo("S1").orElseThrow();
        assertThat(square.outline()).containsExactly(new Vect(2, 3), new Vect(3, 3), new Vect(3, 4), new Vect(2, 4));
        assertThatThrownBy(square::circle).isInstanceOf(IllegalStateException.class);
        BumperView circle = (BumperView) board.gizmo("C1").orElseThrow();
        assertThat(circle.outline()).isEmpty();
        assertThat(circle.circle().getCenter()).isEqualTo(new Vect(5.5, 5.5));
        assertThat(circle.circle().getRadius()).isEqualTo(0.5);
        board.rotate("C1");
        assertThat(circle.rotation()).isZero();
    }

    @Test
    void flipperGeometryFollowsTheContractInEveryRotation() {
        Board board = new Board();
        board.addGizmo(GizmoKind.LEFT_FLIPPER, "L", 4, 6);
        board.addGizmo(GizmoKind.RIGHT_FLIPPER, "R", 8, 6);
        FlipperView left = (FlipperView) board.gizmo("L").orElseThrow();
        FlipperView right = (FlipperView) board.gizmo("R").orElseThrow();
        assertThat(left.pivot()).isEqualTo(new Vect(4.25, 6.25));
        assertThat(left.tip()).isEqualTo(new Vect(4.25, 7.75));
        assertThat(right.pivot()).isEqualTo(new Vect(9.75, 6.25));
        assertThat(right.tip()).isEqualTo(new Vect(9.75, 7.75));
        assertThat(left.radius()).isEqualTo(0.25);
        assertThat(left.angleFromRest()).isZero();
        assertThat(left.isActive()).isFalse();
        assertThat(left.isMoving()).isFalse();
        // a quarter turn clockwise about the box centre (5, 7): the pivot goes to the top-right corner
        board.rotate("L");
        assertThat(left.pivot()).isEqualTo(new Vect(5.75, 6.25));
        assertThat(left.tip()).isEqualTo(new Vect(4.25, 6.25));
        board.rotate("L");
        assertThat(left.pivot()).isEqualTo(new Vect(5.75, 7.75));
        assertThat(left.tip()).isEqualTo(new Vect(5.75, 6.25));
    }

    @Test
    void deletingAGizmoTakesItsConnectionsAndKeyBindingsWithIt() {
        Board board = sample();
        board.delete("LF");
        assertThat(board.gizmo("LF")).isEmpty();
        assertThat(board.gizmoAt(10, 10)).isEmpty();
        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.OUTER_WALLS, "RF"));
        assertThat(board.keyBindings()).isEmpty();
        board.delete("B1");
        assertThat(board.ball("B1")).isEmpty();
        board.delete("A");
        assertThat(board.ball("B2")).as("an absorber takes the balls it holds").isEmpty();
        board.addGizmo(GizmoKind.SQUARE, "LF", 10, 10);   // the name and the cells are free again
    }

    @Test
    void settingABallsVelocityKeepsItWhereItIsAndWhereItIsInTheOrderOfBalls() {
        Board board = sample();
        board.addBall("B3", 10.5, 6.5, 0, 0);
        board.setBallVelocity("B1", -7, 2.5);
        assertThat(board.balls()).extracting(BallView::name).containsExactly("B1", "B2", "B3");
        BallView ball = board.ball("B1").orElseThrow();
        assertThat(ball.position()).isEqualTo(new Vect(1.5, 1.5));
        assertThat(ball.velocity()).isEqualTo(new Vect(-7, 2.5));
        // B2 is held by the absorber: zero is its only velocity.
        board.setBallVelocity("B2", 0, 0);
        assertThatThrownBy(() -> board.setBallVelocity("B2", 0, -50)).isInstanceOf(BoardEditException.class)
                .hasMessageContaining("held by an absorber");
        assertThatThrownBy(() -> board.setBallVelocity("B1", Double.POSITIVE_INFINITY, 0))
                .isInstanceOf(BoardEditException.class).hasMessageContaining("not finite");
        assertThatThrownBy(() -> board.setBallVelocity("Nope", 1, 1)).isInstanceOf(BoardEditException.class)
                .hasMessageContaining("no ball named Nope");
        assertThat(board.ball("B1").orElseThrow().velocity()).isEqualTo(new Vect(-7, 2.5));
    }

    @Test
    void movingAnAbsorberCarriesItsBallsAndMovingABallOutReleasesIt() {
        Board board = sample();
        board.moveGizmo("A", 0, 17);
        assertThat(board.ball("B2").orElseThrow().position()).isEqualTo(new Vect(19.75, 18.75));
        board.moveBall("B2", 10, 13);
        BallView ball = board.ball("B2").orElseThrow();
        assertThat(ball.isCaptured()).isFalse();
        assertThat(ball.position()).isEqualTo(new Vect(10, 13));
        board.moveBall("B2", 3, 18.5);
        assertThat(ball.isCaptured()).isTrue();
        assertThat(ball.position()).isEqualTo(new Vect(19.75, 18.75));
        board.moveGizmo("S1", 0, 0);
        assertThat(board.gizmoAt(0, 0)).map(Gizmo::name).contains("S1");
        assertThat(board.gizmoAt(2, 3)).isEmpty();
        assertThat(((BumperView) board.gizmo("S1").orElseThrow()).outline()).first().isEqualTo(new Vect(0, 0));
    }

    @Test
    void aGroupMovesAsOneSoThatARowMovesAlongItself() {
        Board board = sample();
        board.addGizmo(GizmoKind.SQUARE, "S2", 3, 3);
        board.addGizmo(GizmoKind.SQUARE, "S3", 4, 3);
        board.moveGroup(List.of("S1", "S2", "S3", "B1"), 1, 0);
        assertThat(List.of("S1", "S2", "S3")).extracting(n -> board.gizmo(n).orElseThrow().x()).containsExactly(3, 4, 5);
        assertThat(board.gizmoAt(2, 3)).isEmpty();
        assertThat(board.ball("B1").orElseThrow().position()).isEqualTo(new Vect(2.5, 1.5));
        assertThat(board.ball("B1").orElseThrow().velocity()).isEqualTo(new Vect(3, -4));
        assertThat(board.connections()).contains(new Connection(TriggerSource.gizmo("S1"), "LF"));
        assertThat(board.gizmos()).extracting(Gizmo::name).startsWith("S1", "C1", "T1");

        board.moveGroup(List.of("S1", "S2", "S3"), -1, 0);
        assertThat(board.gizmoAt(2, 3)).map(Gizmo::name).contains("S1");
        assertThat(board.gizmoAt(5, 3)).isEmpty();
    }

    @Test
    void aGroupOfBallsMovesByPartsOfACellAndAnAbsorberOfAGroupCarriesTheBallsItHolds() {
        Board board = sample();
        board.moveGroup(List.of("B1"), 0.25, 0.5);
        assertThat(board.ball("B1").orElseThrow().position()).isEqualTo(new Vect(1.75, 2));

        board.moveGroup(List.of("A", "B2", "RF"), 0, -1);
        assertThat(board.gizmo("A").orElseThrow().y()).isEqualTo(17);
        assertThat(board.gizmo("RF").orElseThrow().y()).isEqualTo(9);
        BallView held = board.ball("B2").orElseThrow();
        assertThat(held.isCaptured()).isTrue();
        assertThat(held.position()).isEqualTo(new Vect(19.75, 18.75));
    }

    @Test
    void aResizedAbsorberKeepsItsPlaceNameLinksAndBallsAndCapturesTheFreeBallsItNowCovers() {
        Board board = sample();
        board.connect(TriggerSource.gizmo("A"), "A");
        board.addBall("B3", 3.5, 16.5, 1, 0);
        board.resizeAbsorber("A", 2, 16, 12, 20);
        Gizmo a = board.gizmo("A").orElseThrow();
        assertThat(List.of(a.x(), a.y(), a.width(), a.height())).containsExactly(2, 16, 10, 4);
        assertThat(board.gizmos()).extracting(Gizmo::name).containsExactly("S1", "C1", "T1", "LF", "RF", "A");
        assertThat(board.gizmoAt(0, 18)).isEmpty();
        assertThat(board.gizmoAt(11, 16)).map(Gizmo::name).contains("A");
        assertThat(board.connections()).contains(new Connection(TriggerSource.gizmo("A"), "A"));
        for (String ball : List.of("B2", "B3")) {
            BallView b = board.ball(ball).orElseThrow();
            assertThat(b.isCaptured()).as(ball).isTrue();
            assertThat(b.position()).as(ball).isEqualTo(new Vect(11.75, 19.75));
        }
    }

    @Test
    void connectionsAndKeyBindingsCanBeRemoved() {
        Board board = sample();
        board.connect(TriggerSource.gizmo("A"), "A");
        board.disconnect(TriggerSource.gizmo("S1"), "LF");
        assertThat(board.connections()).containsExactly(new Connection(TriggerSource.OUTER_WALLS, "RF"),
                new Connection(TriggerSource.gizmo("A"), "A"));
        board.bindKey(32, KeyEdge.UP, "LF");
        board.unbindKey(32, KeyEdge.DOWN, "LF");
        assertThat(board.keyBindings()).containsExactly(new KeyBinding(32, KeyEdge.UP, "LF"));
    }

    @Test
    void placementProblemExplainsOrIsEmpty() {
        Board board = sample();
        assertThat(board.placementProblem(GizmoKind.SQUARE, 0, 0, 1, 1, null)).isEmpty();
        assertThat(board.placementProblem(GizmoKind.SQUARE, 2, 3, 1, 1, null)).get().asString()
                .contains("overlap gizmo S1");
        assertThat(board.placementProblem(GizmoKind.SQUARE, 2, 3, 1, 1, "S1")).isEmpty();
        assertThat(board.placementProblem(GizmoKind.LEFT_FLIPPER, 19, 0, 2, 2, null)).get().asString()
                .contains("cell (20,0) is outside");
        assertThat(board.placementProblem(GizmoKind.ABSORBER, 0, 16, 3, 3, null)).get().asString()
                .contains("overlap gizmo A");
        assertThat(board.placementProblem(GizmoKind.SQUARE, 1, 1, 1, 1, null)).get().asString()
                .contains("overlap ball B1");
    }

    @Test
    void clearEmptiesTheBoardAndRestoresTheDefaults() {
        Board board = sample();
        board.setGravity(10);
        board.setFriction(0, 0);
        board.tick(Board.DEFAULT_TICK);
        board.clear();
        assertThat(board.gizmos()).isEmpty();
        assertThat(board.balls()).isEmpty();
        assertThat(board.connections()).isEmpty();
        assertThat(board.keyBindings()).isEmpty();
        assertThat(List.of(board.gravity(), board.mu(), board.mu2(), board.time()))
                .containsExactly(Board.DEFAULT_GRAVITY, Board.DEFAULT_MU, Board.DEFAULT_MU2, 0.0);
        assertThat(board.gizmoAt(2, 3)).isEmpty();
    }

    @Test
    void copyIsDeepAndReplaceContentsTakesEverything() {
        Board board = sample();
        String before = BoardSnapshot.of(board);
        Board copy = board.copy();
        assertThat(BoardSnapshot.of(copy)).isEqualTo(before);
        copy.moveGizmo("S1", 0, 0);
        copy.rotate("T1");
        copy.trigger("LF");
        copy.tick(0.01);
        copy.delete("B1");
        assertThat(BoardSnapshot.of(board)).isEqualTo(before);

        Board other = new Board();
        List<BoardChange> seen = new ArrayList<>();
        other.addObserver((b, change) -> seen.add(change));
        other.replaceContents(board);
        assertThat(BoardSnapshot.of(other)).isEqualTo(before);
        assertThat(seen).containsExactly(BoardChange.REPLACE);
        other.moveGizmo("S1", 0, 0);
        assertThat(board.gizmoAt(2, 3)).isPresent();
    }

    @Test
    void observersHearEditsReplacementsAndTicksButNotRefusals() {
        Board board = new Board();
        List<BoardChange> seen = new ArrayList<>();
        BoardObserver observer = (b, change) -> {
            assertThat(b).isSameAs(board);
            seen.add(change);
        };
        board.addObserver(observer);
        board.addGizmo(GizmoKind.SQUARE, "S", 1, 1);
        assertThatThrownBy(() -> board.addGizmo(GizmoKind.SQUARE, "S", 2, 2)).isInstanceOf(BoardEditException.class);
        board.tick(Board.DEFAULT_TICK);
        board.clear();
        board.removeObserver(observer);
        board.addGizmo(GizmoKind.SQUARE, "S", 1, 1);
        assertThat(seen).containsExactly(BoardChange.EDIT, BoardChange.TICK, BoardChange.REPLACE);
    }

    static Stream<Arguments> refusals() {
        return Stream.of(
                refusal("name reused by a gizmo", b -> b.addGizmo(GizmoKind.SQUARE, "S1", 0, 0), "name S1 is already used"),
                refusal("name reused by a ball", b -> b.addGizmo(GizmoKind.SQUARE, "B1", 0, 0), "name B1 is already used"),
                refusal("ball named like a gizmo", b -> b.addBall("C1", 10, 10, 0, 0), "name C1 is already used"),
                refusal("reserved name", b -> b.addGizmo(GizmoKind.SQUARE, TriggerSource.OuterWalls.NAME, 0, 0),
                        "reserved"),
                refusal("empty name", b -> b.addGizmo(GizmoKind.SQUARE, "", 0, 0), "non-empty"),
                refusal("name with a space", b -> b.addGizmo(GizmoKind.SQUARE, "a b", 0, 0), "whitespace"),
                refusal("null name", b -> b.addBall(null, 10, 10, 0, 0), "non-empty"),
                refusal("absorber through addGizmo", b -> b.addGizmo(GizmoKind.ABSORBER, "X", 0, 0), "absorbers"),
                refusal("overlap", b -> b.addGizmo(GizmoKind.CIRCLE, "X", 2, 3), "gizmo X at (2,3) would overlap gizmo S1"),
                refusal("flipper overlapping a square", b -> b.addGizmo(GizmoKind.LEFT_FLIPPER, "X", 1, 2), "overlap gizmo S1"),
                refusal("outside right", b -> b.addGizmo(GizmoKind.SQUARE, "X", 20, 3), "cell (20,3) is outside"),
                refusal("outside top", b -> b.addGizmo(GizmoKind.SQUARE, "X", 3, -1), "cell (3,-1) is outside"),
                refusal("flipper sticking out", b -> b.addGizmo(GizmoKind.RIGHT_FLIPPER, "X", 19, 5), "cell (20,5) is outside"),
                refusal("gizmo on a ball", b -> b.addGizmo(GizmoKind.SQUARE, "X", 1, 1), "overlap ball B1"),
                refusal("absorber outside", b -> b.addAbsorber("X", 15, 0, 21, 2), "cell (20,0) is outside"),
                refusal("empty absorber", b -> b.addAbsorber("X", 5, 5, 5, 7), "at least one cell"),
                refusal("absorber overlapping", b -> b.addAbsorber("X", 0, 17, 3, 19), "overlap gizmo A"),
                refusal("ball outside", b -> b.addBall("X", 0.2, 10, 0, 0), "outside the board"),
                refusal("ball beyond the floor", b -> b.addBall("X", 10, 21, 0, 0), "outside the board"),
                refusal("ball NaN", b -> b.addBall("X", Double.NaN, 10, 0, 0), "not a finite number"),
                refusal("ball infinite velocity", b -> b.addBall("X", 10, 10, Double.POSITIVE_INFINITY, 0), "finite"),
                refusal("ball in a square", b -> b.addBall("X", 2.5, 2.9, 0, 0), "would overlap gizmo S1"),
                refusal("ball in a circle", b -> b.addBall("X", 5.5, 6.2, 0, 0), "would overlap gizmo C1"),
                refusal("ball on a flipper", b -> b.addBall("X", 10.3, 11, 0, 0), "would overlap gizmo LF"),
                refusal("ball on a ball", b -> b.addBall("X", 1.8, 1.5, 0, 0), "would overlap ball B1"),
                refusal("rotate unknown", b -> b.rotate("Nope"), "no gizmo named Nope"),
                refusal("rotate a ball", b -> b.rotate("B1"), "B1 is a ball, not a gizmo"),
                refusal("delete unknown", b -> b.delete("Nope"), "no gizmo or ball named Nope"),
                refusal("move onto a gizmo", b -> b.moveGizmo("S1", 5, 5), "would overlap gizmo C1"),
                refusal("move off the board", b -> b.moveGizmo("LF", 19, 19), "outside"),
                refusal("move unknown", b -> b.moveGizmo("Nope", 1, 1), "no gizmo named Nope"),
                refusal("move onto a ball", b -> b.moveGizmo("C1", 1, 1), "overlap ball B1"),
                refusal("move a group onto a gizmo", b -> b.moveGroup(List.of("S1", "T1"), 3, 2), "would overlap gizmo C1"),
                refusal("move a group's ball into a gizmo", b -> b.moveGroup(List.of("S1", "B1"), 4, 4),
                        "would overlap gizmo C1"),
                refusal("move a group off the board", b -> b.moveGroup(List.of("S1", "T1"), 13, 0), "outside"),
                refusal("move a group's gizmos by part of a cell", b -> b.moveGroup(List.of("S1", "B1"), 0.25, 0),
                        "whole cells"),
                refusal("move a group with an unknown", b -> b.moveGroup(List.of("S1", "Nope"), 1, 0),
                        "no gizmo or ball named Nope"),
                refusal("resize onto a gizmo", b -> b.resizeAbsorber("A", 0, 10, 20, 20), "would overlap gizmo LF"),
                refusal("resize to nothing", b -> b.resizeAbsorber("A", 0, 18, 0, 20), "at least one cell"),
                refusal("resize off the board", b -> b.resizeAbsorber("A", 0, 18, 21, 20), "outside"),
                refusal("resize a square", b -> b.resizeAbsorber("S1", 2, 3, 4, 4), "not an absorber"),
                refusal("move ball unknown", b -> b.moveBall("Nope", 1, 1), "no ball named Nope"),
                refusal("move ball into a gizmo", b -> b.moveBall("B1", 2.5, 3.5), "would overlap gizmo S1"),
                refusal("move ball outside", b -> b.moveBall("B1", 25, 3.5), "outside the board"),
                refusal("connect unknown source", b -> b.connect(TriggerSource.gizmo("Nope"), "S1"), "no gizmo named Nope"),
                refusal("connect unknown target", b -> b.connect(TriggerSource.gizmo("S1"), "Nope"), "no gizmo named Nope"),
                refusal("connect to a ball", b -> b.connect(TriggerSource.gizmo("S1"), "B1"), "B1 is a ball"),
                refusal("connect to the walls", b -> b.connect(TriggerSource.gizmo("S1"), TriggerSource.OuterWalls.NAME),
                        "no gizmo named OuterWalls"),
                refusal("connect twice", b -> b.connect(TriggerSource.gizmo("S1"), "LF"), "connection S1 \u2192 LF already exists"),
                refusal("disconnect missing", b -> b.disconnect(TriggerSource.gizmo("S1"), "C1"), "no connection S1 \u2192 C1"),
                refusal("bind negative key", b -> b.bindKey(-1, KeyEdge.DOWN, "LF"), "key code"),
                refusal("bind unknown", b -> b.bindKey(32, KeyEdge.UP, "Nope"), "no gizmo named Nope"),
                refusal("bind twice", b -> b.bindKey(32, KeyEdge.DOWN, "LF"), "key 32 down is already bound to LF"),
                refusal("bind without edge", b -> b.bindKey(32, null, "LF"), "edge"),
                refusal("unbind missing", b -> b.unbindKey(32, KeyEdge.UP, "LF"), "key 32 up is not bound to LF"),
                refusal("gravity NaN", b -> b.setGravity(Double.NaN), "gravity"),
                refusal("gravity infinite", b -> b.setGravity(Double.NEGATIVE_INFINITY), "gravity"),
                refusal("negative friction", b -> b.setFriction(-0.1, 0), "friction"),
                refusal("infinite friction", b -> b.setFriction(0, Double.POSITIVE_INFINITY), "friction"));
    }

    private static Arguments refusal(String what, Consumer<Board> edit, String message) {
        return Arguments.of(what, edit, message);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("refusals")
    void everyRefusalSaysWhyAndLeavesTheBoardExactlyAsItWas(String what, Consumer<Board> edit, String message) {
        Board board = sample();
        board.tick(0.05);   // some play state too: flippers, time
        String before = BoardSnapshot.of(board.copy());
        List<BoardChange> seen = new ArrayList<>();
        board.addObserver((b, change) -> seen.add(change));
        assertThatThrownBy(() -> edit.accept(board))
                .isInstanceOf(BoardEditException.class)
                .hasMessageContaining(message);
        assertThat(BoardSnapshot.of(board)).isEqualTo(before);
        assertThat(seen).isEmpty();
    }

    @Test
    void rotatingATriangleOntoABallIsRefused() {
        Board board = sample();
        board.addBall("Y", 7.8, 2.8, 0, 0);   // clear of the hypotenuse x + y = 10, on the turned one x - y = 5
        String before = BoardSnapshot.of(board);
        assertThatThrownBy(() -> board.rotate("T1")).isInstanceOf(BoardEditException.class)
                .hasMessageContaining("rotating T1 would make it overlap ball Y");
        assertThat(BoardSnapshot.of(board)).isEqualTo(before);
    }

    /** The balls whose disc contains the point. */
    private static java.util.List<String> ballsCovering(Board board, double x, double y) {
        Vect point = new Vect(x, y);
        return board.balls().stream()
                .filter(b -> b.position().distanceSquared(point) <= b.radius() * b.radius())
                .map(BallView::name).toList();
    }
}
