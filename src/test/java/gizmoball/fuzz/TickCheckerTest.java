package gizmoball.fuzz;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Absorber;
import gizmoball.model.gizmo.Bumper;
import gizmoball.model.gizmo.Flipper;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Portal;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.gizmo.Spawner;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.PlayEvent;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import physics.Vect;

/**
 * The fuzz checker finds what it is for, at the tolerance and not below it: overlaps planted with balls made where the
 * board would refuse them, frozen balls, energy gained; and its own shapes are where the product description puts the
 * gizmos (checked against the kinds' read-only accessors).
 */
class TickCheckerTest {
    private static final double R = Board.BALL_RADIUS;

    private static Gizmo gizmo(GizmoKind kind, int x, int y) {
        return (Gizmo) kind.create(kind.name(), x, y);
    }

    private static Ball ball(String name, double x, double y, double vx, double vy) {
        return new Ball(name, new Vect(x, y), new Vect(vx, vy));
    }

    private static List<Violation.Kind> kinds(List<Violation> found) {
        return found.stream().map(Violation::kind).toList();
    }

    private static List<Violation> once(List<Gizmo> gizmos, double gravity, Ball... balls) {
        return new TickChecker(gizmos, gravity, 0, 0, List.of(balls)).check(List.of(balls), 1);
    }

    @Test
    void aBallDeeperInASquareThanTheToleranceIsInsideIt() {
        Gizmo square = gizmo(GizmoKind.SQUARE, 5, 5);
        List<Violation> deep = once(List.of(square), 0, ball("B", 5.5, 5 - R + 2e-6, 0, 0));
        assertThat(kinds(deep)).containsExactly(Violation.Kind.INSIDE_GIZMO);
        assertThat(deep.get(0).amount()).isCloseTo(2e-6, within(1e-12));
        assertThat(once(List.of(square), 0, ball("B", 5.5, 5 - R + 0.5e-6, 0, 0))).isEmpty();
        // At a corner the distance is to the corner point, not to the lines of the sides.
        double diagonal = (R - 2e-6) / Math.sqrt(2);
        assertThat(kinds(once(List.of(square), 0, ball("B", 5 - diagonal, 5 - diagonal, 0, 0))))
                .containsExactly(Violation.Kind.INSIDE_GIZMO);
        assertThat(once(List.of(square), 0, ball("B", 5 - R / Math.sqrt(2), 5 - R / Math.sqrt(2), 0, 0))).isEmpty();
    }

    @Test
    void aBallInsideACircleOrATrianglesHypotenuseIsInsideIt() {
        Gizmo circle = gizmo(GizmoKind.CIRCLE, 2, 2);
        assertThat(kinds(once(List.of(circle), 0, ball("B", 2.5 + 0.75 - 1e-5, 2.5, 0, 0))))
                .containsExactly(Violation.Kind.INSIDE_GIZMO);
        assertThat(once(List.of(circle), 0, ball("B", 2.5 + 0.75, 2.5, 0, 0))).isEmpty();
        // The unturned triangle's hypotenuse runs from (x + 1, y) to (x, y + 1); outside it lies toward +x +y.
        Gizmo triangle = gizmo(GizmoKind.TRIANGLE, 8, 8);
        double along = (R - 1e-5) / Math.sqrt(2);
        assertThat(kinds(once(List.of(triangle), 0, ball("B", 8.5 + along, 8.5 + along, 0, 0))))
                .containsExactly(Violation.Kind.INSIDE_GIZMO);
        double clear = (R + 1e-9) / Math.sqrt(2);
        assertThat(once(List.of(triangle), 0, ball("B", 8.5 + clear, 8.5 + clear, 0, 0))).isEmpty();
    }

    /** A left flipper at (4, 4) turned 45 degrees: its bar runs from the pivot (4.25, 4.25) along (sin, cos) 45. */
    @Test
    void aBallInsideAFlipperAtItsCurrentAngleIsInsideIt() {
        Flipper flipper = (Flipper) gizmo(GizmoKind.LEFT_FLIPPER, 4, 4);
        flipper.setState(45, true);
        double s = Math.sqrt(0.5);
        // 1 L along the bar, then out across it (direction (s, -s)) to 0.5 L minus 3e-6 from its axis.
        double depth = 3e-6;
        double out = 0.25 + R - depth;
        Ball inside = ball("B", 4.25 + s + out * s, 4.25 + s - out * s, 0, 0);
        List<Violation> found = once(List.of(flipper), 0, inside);
        assertThat(kinds(found)).containsExactly(Violation.Kind.INSIDE_GIZMO);
        assertThat(found.get(0).amount()).isCloseTo(depth, within(1e-12));
        // The same point is clear of the flipper at rest, which hangs straight down from the pivot.
        flipper.setState(0, false);
        assertThat(once(List.of(flipper), 0, inside)).isEmpty();
        // Beyond the tip the bar is round: 0.5 L from the tip's centre is touching.
        flipper.setState(90, true);
        assertThat(once(List.of(flipper), 0, ball("B", 4.25 + 1.5 + 0.5, 4.25, 0, 0))).isEmpty();
        assertThat(kinds(once(List.of(flipper), 0, ball("B", 4.25 + 1.5 + 0.5 - 2e-6, 4.25, 0, 0))))
                .containsExactly(Violation.Kind.INSIDE_GIZMO);
    }

    @Test
    void overlappingBallsEscapesAndInfinitiesAreFound() {
        assertThat(kinds(once(List.of(), 0, ball("A", 10, 10, 0, 0), ball("B", 10.5 - 2e-6, 10, 0, 0))))
                .containsExactly(Violation.Kind.INSIDE_BALL);
        assertThat(once(List.of(), 0, ball("A", 10, 10, 0, 0), ball("B", 10.5, 10, 0, 0))).isEmpty();
        assertThat(kinds(once(List.of(), 0, ball("A", R - 2e-6, 10, 0, 0)))).containsExactly(Violation.Kind.ESCAPED);
        assertThat(kinds(once(List.of(), 0, ball("A", 10, Board.SIZE - R + 2e-6, 0, 0))))
                .containsExactly(Violation.Kind.ESCAPED);
        // physics.Vect refuses NaN, so what the board can hold that is not a number is an infinity.
        assertThat(kinds(once(List.of(), 0, ball("A", 10, 10, Double.POSITIVE_INFINITY, 0))))
                .containsExactly(Violation.Kind.NOT_A_NUMBER);
    }

    @Test
    void aBallClaimingAVelocityThatStaysPutInMidAirIsFrozenUnlessItTouchesSomething() {
        Ball flying = ball("B", 10, 10, 26, 0);
        TickChecker checker = new TickChecker(List.of(), 25, 0, 0, List.of(flying));
        assertThat(checker.check(List.of(flying), 0)).isEmpty();
        assertThat(kinds(checker.check(List.of(flying), 1))).containsExactly(Violation.Kind.FROZEN);
        flying.moveTo(new Vect(10.4, 10));
        assertThat(checker.check(List.of(flying), 2)).isEmpty();

        Gizmo square = gizmo(GizmoKind.SQUARE, 11, 9);
        Ball pressed = ball("B", 11 - R, 9.5, 26, 0);
        TickChecker touching = new TickChecker(List.of(square), 25, 0, 0, List.of(pressed));
        touching.check(List.of(pressed), 0);
        assertThat(touching.check(List.of(pressed), 1)).isEmpty();
    }

    @Test
    void aBallAtRestInMidAirUnderGravityIsFrozenButNotAtTheTopOfAThrowNorWithoutGravity() {
        Ball still = ball("B", 10, 10, 0, 0);
        TickChecker checker = new TickChecker(List.of(), 25, 0, 0, List.of(still));
        checker.check(List.of(still), 0);
        assertThat(kinds(checker.check(List.of(still), 1))).containsExactly(Violation.Kind.FROZEN);

        // Going up at exactly one tick of gravity, the tick's gravity stops it first: it may stay put for that tick.
        Ball apex = ball("B", 10, 10, 0, -25 * Board.DEFAULT_TICK);
        TickChecker top = new TickChecker(List.of(), 25, 0, 0, List.of(apex));
        top.check(List.of(apex), 0);
        apex.setVelocity(new Vect(0, 0));
        assertThat(top.check(List.of(apex), 1)).isEmpty();

        TickChecker weightless = new TickChecker(List.of(), 0, 0, 0, List.of(still));
        for (int tick = 0; tick < 3; tick++) {
            assertThat(weightless.check(List.of(still), tick)).isEmpty();
        }
    }

    /** mu2 |v| dt = 0.9 x 80 / 60 > 1: the tick's friction stops the ball where it is, which is no freeze. */
    @Test
    void aBallStoppedByFrictionStrongerThanItsSpeedIsNotFrozen() {
        Ball braked = ball("B", 10, 10, 80, 0);
        TickChecker checker = new TickChecker(List.of(), 0, 0.1, 0.9, List.of(braked));
        checker.check(List.of(braked), 0);
        braked.setVelocity(Vect.ZERO);
        assertThat(checker.check(List.of(braked), 1)).isEmpty();
    }

    /** 1e-4 L above a square, falling, not moving: near enough to have landed in the tick, so noted, not frozen. */
    @Test
    void aBallKeptStillNearASurfaceItDoesNotTouchIsHovering() {
        Ball above = ball("B", 5.5, 5 - R - 1e-4, 0, 0);
        TickChecker checker = new TickChecker(List.of(gizmo(GizmoKind.SQUARE, 5, 5)), 25, 0, 0, List.of(above));
        checker.check(List.of(above), 0);
        List<Violation> found = checker.check(List.of(above), 1);
        assertThat(kinds(found)).containsExactly(Violation.Kind.HOVERING);
        assertThat(found.get(0).amount()).isCloseTo(1e-4, within(1e-12));
        assertThat(Violation.Kind.HOVERING.rule()).isFalse();
    }

    /** Another ball that passed near within the tick could have met it: then a still ball is not in free flight. */
    @Test
    void aBallAnotherBallPassedCloseToInTheTickIsNotFrozen() {
        Ball still = ball("A", 10, 10, 5, 0);
        Ball passing = ball("B", 9, 10.55, 60, 0);
        TickChecker checker = new TickChecker(List.of(), 0, 0, 0, List.of(still, passing));
        checker.check(List.of(still, passing), 0);
        passing.moveTo(new Vect(11, 10.55));
        assertThat(kinds(checker.check(List.of(still, passing), 1))).containsExactly(Violation.Kind.HOVERING);
    }

    /**
     * Fuzz seed 1000872: an absorber fired a ball up into one coming down, which went back up where it came from as
     * the fired one fell back in, held at both ends of the tick. The ball is where it was, but not frozen: the fired
     * ball's way out and back passed it. Had the absorber not fired, nothing came within its reach.
     */
    @Test
    void aBallMetByOneAnAbsorberFiredAndCaughtAgainInTheTickIsNotFrozen() {
        Gizmo absorber = new Absorber("A0", 2, 5, 1, 1);
        Ball still = ball("A", 2.5, 3.5, 0, 50);
        TickChecker checker = new TickChecker(List.of(absorber), 25, 0, 0, List.of(still));
        checker.check(List.of(still), 0);
        assertThat(kinds(checker.check(List.of(still), 1, List.of(new PlayEvent.Fired(absorber.name())))))
                .containsExactly(Violation.Kind.HOVERING);
        assertThat(kinds(checker.check(List.of(still), 2))).containsExactly(Violation.Kind.FROZEN);
    }

    /** A spawner at (5, 5) facing up: its mouth is (5.5, 5 - R); its balls start at (3, -4). */
    private static Spawner spawner() {
        Spawner spawner = (Spawner) GizmoKind.SPAWNER.create("SP", 5, 5);
        spawner.hold(new Setting.Launch(3, -4), name -> null);
        return spawner;
    }

    @Test
    void aBallAppearsOnlyAtASpawnersMouthWithItsVelocityAndTheNextReportNamesItsSpawn() {
        Ball there = ball("A", 15, 15, 0, 0);
        TickChecker checker = new TickChecker(List.of(spawner()), 0, 0, 0, List.of(there));
        assertThat(checker.check(List.of(there), 0)).isEmpty();
        Ball spawned = ball("N", 5.5, 5 - R, 3, -4);
        assertThat(checker.check(List.of(there, spawned), 1)).as("spawned at the tick's end").isEmpty();
        spawned.moveTo(new Vect(7.5, 3));
        spawned.setVelocity(Vect.ZERO);   // and stops there, so that it is no frozen ball below
        assertThat(checker.check(List.of(there, spawned), 2, List.of(new PlayEvent.Spawned("SP", "N")))).isEmpty();
        Ball unnamed = ball("M", 5.5, 5 - R, 3, -4);
        assertThat(checker.check(List.of(there, spawned, unnamed), 3)).isEmpty();
        assertThat(kinds(checker.check(List.of(there, spawned, unnamed), 4))).as("no report named it")
                .containsExactly(Violation.Kind.APPEARED);

        List<BallView> elsewhere = List.of(there, ball("N", 10, 10, 3, -4));
        TickChecker nowhere = new TickChecker(List.of(spawner()), 0, 0, 0, List.of(there));
        nowhere.check(List.of(there), 0);
        assertThat(kinds(nowhere.check(elsewhere, 1))).containsExactly(Violation.Kind.APPEARED);
        TickChecker tooFast = new TickChecker(List.of(spawner()), 0, 0, 0, List.of(there));
        tooFast.check(List.of(there), 0);
        assertThat(kinds(tooFast.check(List.of(there, ball("N", 5.5, 5 - R, 3, -4.001)), 1)))
                .containsExactly(Violation.Kind.APPEARED);
        TickChecker off = new TickChecker(List.of(spawner()), 0, 0, 0, List.of(there));
        off.check(List.of(there), 0);
        assertThat(kinds(off.check(List.of(there, ball("N", 5.5, 5 - R - 1e-6, 3, -4)), 1)))
                .containsExactly(Violation.Kind.APPEARED);
        TickChecker ghost = new TickChecker(List.of(spawner()), 0, 0, 0, List.of(there));
        ghost.check(List.of(there), 0);
        assertThat(kinds(ghost.check(List.of(there), 1, List.of(new PlayEvent.Spawned("SP", "N")))))
                .as("a spawn reported of a ball never seen").containsExactly(Violation.Kind.APPEARED);
    }

    @Test
    void aBallLeavesOnlyIntoASinkItTouchedInTheTickThatSaysSo() {
        Gizmo sink = gizmo(GizmoKind.SINK, 5, 5);
        Ball onTop = ball("B", 5.5, 5 - R, 0, 1);
        Vect touching = new Vect(5.5, 5 - R);
        TickChecker taken = new TickChecker(List.of(sink), 25, 0, 0, List.of(onTop));
        taken.check(List.of(onTop), 0);
        assertThat(taken.check(List.of(), 1, List.of(new PlayEvent.Sunk("SINK", "B", touching)))).isEmpty();

        TickChecker gone = new TickChecker(List.of(sink), 25, 0, 0, List.of(onTop));
        gone.check(List.of(onTop), 0);
        assertThat(kinds(gone.check(List.of(), 1))).containsExactly(Violation.Kind.VANISHED);
        TickChecker far = new TickChecker(List.of(sink), 25, 0, 0, List.of(onTop));
        far.check(List.of(onTop), 0);
        assertThat(kinds(far.check(List.of(), 1, List.of(new PlayEvent.Sunk("SINK", "B", new Vect(5.5, 5 - R - 2e-6))))))
                .as("taken from beyond touching").containsExactly(Violation.Kind.VANISHED);
        TickChecker stays = new TickChecker(List.of(sink), 25, 0, 0, List.of(onTop));
        stays.check(List.of(onTop), 0);
        assertThat(kinds(stays.check(List.of(onTop), 1, List.of(new PlayEvent.Sunk("SINK", "B", touching)))))
                .as("taken, yet still there").containsExactly(Violation.Kind.VANISHED);
    }

    /**
     * Every pair of rotations: the game's own passage (Portal.passage) is where the checker's frame puts the ball, and
     * a way out 2e-9 L from it, or through portals that are no pair, or from off the mouth, is found.
     */
    @Test
    void aBallThroughAPortalLeavesWhereItsPairsFrameSays() {
        Ball elsewhere = ball("C", 10, 2, 0, 0);
        for (int a = 0; a < 4; a++) {
            for (int b = 0; b < 4; b++) {
                Board board = new Board();
                board.addGizmo(GizmoKind.PORTAL, "A", 4, 10);
                board.addGizmo(GizmoKind.PORTAL, "Z", 14, 10);
                board.addGizmo(GizmoKind.PORTAL, "Y", 10, 15);
                for (int t = 0; t < a; t++) {
                    board.rotate("A");
                }
                for (int t = 0; t < b; t++) {
                    board.rotate("Z");
                }
                board.set("A", Setting.Pair.with("Z"));
                Portal entry = (Portal) board.gizmos().stream().filter(g -> g.name().equals("A")).findFirst().orElseThrow();
                Portal exit = (Portal) board.gizmos().stream().filter(g -> g.name().equals("Z")).findFirst().orElseThrow();
                Vect n = entry.facing();
                Vect at = entry.mouthCentre().plus(n.times(R)).plus(new Vect(-n.y(), n.x()).times(0.3));
                Vect out = entry.passage(at, new Vect(0, 1), exit, R).centre();
                String as = "entry turned " + a + ", exit turned " + b;
                TickChecker checker = new TickChecker(board.gizmos(), 0, 0, 0, List.of(elsewhere));
                assertThat(checker.check(List.of(elsewhere), 1,
                        List.of(new PlayEvent.Teleported("A", "Z", "B", at, out)))).as(as).isEmpty();
                assertThat(kinds(checker.check(List.of(elsewhere), 2, List.of(new PlayEvent.Teleported("A", "Z", "B",
                        at, out.plus(new Vect(2e-9, 0))))))).as(as).containsExactly(Violation.Kind.JUMPED);
                assertThat(kinds(checker.check(List.of(elsewhere), 3, List.of(new PlayEvent.Teleported("A", "Y", "B",
                        at, out))))).as(as).containsExactly(Violation.Kind.JUMPED);
                Vect beside = at.plus(new Vect(-n.y(), n.x()).times(0.3));   // 0.6 along: beyond the mouth's half
                assertThat(kinds(checker.check(List.of(elsewhere), 4, List.of(new PlayEvent.Teleported("A", "Z", "B",
                        beside, entry.passage(beside, new Vect(0, 1), exit, R).centre())))))
                        .as(as).containsExactly(Violation.Kind.JUMPED);
            }
        }
    }

    @Test
    void kineticEnergyGainedIsFoundOnlyWhereEnergyIsKept() {
        Ball ball = ball("B", 10, 10, 3, 4);
        TickChecker kept = new TickChecker(List.of(gizmo(GizmoKind.SQUARE, 1, 1)), 0, 0, 0, List.of(ball));
        assertThat(kept.checksEnergy()).isTrue();
        ball.moveTo(new Vect(10.1, 10));
        ball.setVelocity(new Vect(3, 4 * (1 + 1e-10)));
        assertThat(kept.check(List.of(ball), 1)).as("rounding").isEmpty();
        ball.moveTo(new Vect(10.2, 10));
        ball.setVelocity(new Vect(3, 4.001));
        assertThat(kinds(kept.check(List.of(ball), 2))).containsExactly(Violation.Kind.ENERGY_GAINED);

        Ball other = ball("B", 10, 10, 3, 4);
        TickChecker falling = new TickChecker(List.of(), 25, 0, 0, List.of(other));
        assertThat(falling.checksEnergy()).isFalse();
        other.setVelocity(new Vect(3, 5));
        other.moveTo(new Vect(10.1, 10));
        assertThat(falling.check(List.of(other), 1)).isEmpty();
        assertThat(new TickChecker(List.of(gizmo(GizmoKind.LEFT_FLIPPER, 1, 1)), 0, 0, 0, List.of(other))
                .checksEnergy()).as("a flipper can bat").isFalse();
    }

    @ParameterizedTest
    @EnumSource(value = GizmoKind.class, names = {"LEFT_FLIPPER", "RIGHT_FLIPPER"})
    void theCheckersFlipperIsTheFlippersOwnInEveryRotationAndAngle(GizmoKind kind) {
        for (int turns = 0; turns < 4; turns++) {
            Flipper flipper = (Flipper) gizmo(kind, 6, 3);
            for (int t = 0; t < turns; t++) {
                flipper.rotateClockwise();
            }
            for (double degrees : new double[] {0, 17.5, 45, 89.9, 90}) {
                flipper.setState(degrees, true);
                Solid.Capsule bar = Bodies.flipper(flipper);
                String as = kind + " turned " + turns + " at " + degrees;
                assertThat(bar.a().x()).as(as).isCloseTo(flipper.pivot().x(), within(1e-12));
                assertThat(bar.a().y()).as(as).isCloseTo(flipper.pivot().y(), within(1e-12));
                assertThat(bar.b().x()).as(as).isCloseTo(flipper.tip().x(), within(1e-12));
                assertThat(bar.b().y()).as(as).isCloseTo(flipper.tip().y(), within(1e-12));
                assertThat(bar.radius()).isEqualTo(flipper.radius());
            }
        }
    }

    @Test
    void theCheckersTriangleHasTheBumpersCornersInEveryRotation() {
        Bumper triangle = (Bumper) gizmo(GizmoKind.TRIANGLE, 3, 7);
        for (int turns = 0; turns < 4; turns++) {
            Solid.Polygon body = (Solid.Polygon) Bodies.of(triangle);
            assertThat(body.corners()).as("turned %d", turns).containsExactlyInAnyOrderElementsOf(
                    triangle.outline().stream().map(v -> new Point(v.x(), v.y())).toList());
            triangle.rotateClockwise();
        }
    }
}
