package gizmoball.model;

import gizmoball.model.gizmo.Setting;
import java.util.Optional;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.PortalView;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.PlayEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import physics.Vect;

/**
 * Portals (docs/design.md, "Portals"), played on a board without gravity or friction, so that a ball flies straight
 * and every expected number is a closed form. In the frame of a portal facing n (its mouth's outward normal) with e
 * the mouth's direction clockwise of n, a ball meeting the mouth at offset t along e with velocity -s n + u e leaves
 * its pair (n', e') at r n' - t e' from the pair's mouth centre with velocity s n' - u e': what goes in comes out,
 * turned by the portals' relative rotation.
 */
class PortalTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = Board.BALL_RADIUS;
    /** The mouth's outward normal of a portal turned k quarter turns: up, right, down, left. */
    private static final Vect[] FACING = {new Vect(0, -1), new Vect(1, 0), new Vect(0, 1), new Vect(-1, 0)};
    /** L/s: the ball's speed into the mouth and along it. */
    private static final double IN = 6;
    private static final double ALONG = 1.5;
    /** L: where the ball starts, beyond touching the mouth and along it from the mouth's centre. */
    private static final double GAP = 1.05;
    private static final double OFFSET = 0.125;
    private static final int TICKS = 20;

    private static Board board() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        return board;
    }

    private static void portal(Board board, String name, int x, int y, int turns) {
        board.addGizmo(GizmoKind.PORTAL, name, x, y);
        for (int t = 0; t < turns; t++) {
            board.rotate(name);
        }
    }

    private static Vect mouthCentre(int x, int y, int turns) {
        return new Vect(x + 0.5, y + 0.5).plus(FACING[turns].times(0.5));
    }

    private static Vect along(int turns) {
        return FACING[(turns + 1) % 4];
    }

    /** The ball "B" aimed at the mouth of a portal at (x, y) turned {@code turns}: GAP away, OFFSET along it. */
    private static void aimAt(Board board, int x, int y, int turns) {
        Vect n = FACING[turns];
        Vect start = mouthCentre(x, y, turns).plus(n.times(R + GAP)).plus(along(turns).times(OFFSET));
        Vect v = n.times(-IN).plus(along(turns).times(ALONG));
        board.addBall("B", start.x(), start.y(), v.x(), v.y());
    }

    private static List<PlayEvent> play(Board board) {
        List<PlayEvent> events = new ArrayList<>();
        for (int i = 0; i < TICKS; i++) {
            board.tick(DT);
            events.addAll(board.lastTick().events());
            assertThat(Invariants.violations(board)).as("after tick " + (i + 1)).isEmpty();
        }
        return events;
    }

    private static BallView ball(Board board) {
        return board.ball("B").orElseThrow();
    }

    static Stream<Arguments> everyPairOfRotations() {
        List<Arguments> pairs = new ArrayList<>();
        for (int a = 0; a < 4; a++) {
            for (int b = 0; b < 4; b++) {
                pairs.add(Arguments.of(a, b));
            }
        }
        return pairs.stream();
    }

    @ParameterizedTest(name = "entry turned {0}, exit turned {1}")
    @MethodSource("everyPairOfRotations")
    void aBallEnteringTheMouthLeavesThePairsMouthTurnedByTheirRelativeRotation(int a, int b) {
        Board board = board();
        portal(board, "A", 4, 10, a);
        portal(board, "Z", 14, 10, b);
        board.set("A", Setting.Pair.with("Z"));
        aimAt(board, 4, 10, a);
        List<PlayEvent> events = play(board);

        // It touches the mouth after GAP / IN s (10.5 ticks), OFFSET + ALONG * that along it.
        double contact = GAP / IN;
        double t = OFFSET + ALONG * contact;
        Vect n = FACING[b];
        Vect e = along(b);
        Vect out = n.times(IN).minus(e.times(ALONG));
        Vect at = mouthCentre(14, 10, b).plus(n.times(R)).minus(e.times(t));
        Vect expected = at.plus(out.times(TICKS * DT - contact));
        assertThat(ball(board).velocity()).isEqualTo(out);   // exact: a quarter turn swaps and negates
        assertThat(ball(board).position().x()).isCloseTo(expected.x(), within(1e-12));
        assertThat(ball(board).position().y()).isCloseTo(expected.y(), within(1e-12));
        PlayEvent.Teleported through = (PlayEvent.Teleported) events.stream()
                .filter(PlayEvent.Teleported.class::isInstance).findFirst().orElseThrow();
        assertThat(events).filteredOn(PlayEvent.Teleported.class::isInstance).singleElement()
                .isEqualTo(new PlayEvent.Teleported("A", "Z", "B", through.at(), through.out()));
        assertThat(through.out().x()).isCloseTo(at.x(), within(1e-12));   // where it left: touching Z's mouth
        assertThat(through.out().y()).isCloseTo(at.y(), within(1e-12));
        assertThat(events).as("no bounce").noneMatch(PlayEvent.Hit.class::isInstance);
    }

    /** The bounce off the mouth as off a wall: the normal part reversed, exactly; then straight on to the end. */
    private static void assertBouncedOffTheMouth(Board board, int x, int y, int turns) {
        double contact = GAP / IN;
        Vect n = FACING[turns];
        Vect e = along(turns);
        Vect at = mouthCentre(x, y, turns).plus(n.times(R)).plus(e.times(OFFSET + ALONG * contact));
        Vect bounced = n.times(IN).plus(e.times(ALONG));
        Vect expected = at.plus(bounced.times(TICKS * DT - contact));
        assertThat(ball(board).velocity()).isEqualTo(bounced);
        assertThat(ball(board).position().x()).isCloseTo(expected.x(), within(1e-12));
        assertThat(ball(board).position().y()).isCloseTo(expected.y(), within(1e-12));
    }

    @Test
    void aBallWhoseWayOutAGizmoBlocksBouncesOffTheMouthAsOffAWall() {
        Board board = board();
        portal(board, "A", 4, 10, 0);
        portal(board, "Z", 14, 10, 1);
        board.addGizmo(GizmoKind.SQUARE, "S", 15, 10);   // in front of Z's mouth, which faces right
        board.set("A", Setting.Pair.with("Z"));
        aimAt(board, 4, 10, 0);
        List<PlayEvent> events = play(board);
        assertBouncedOffTheMouth(board, 4, 10, 0);
        assertThat(events).noneMatch(PlayEvent.Teleported.class::isInstance);
        assertThat(events).filteredOn(PlayEvent.Hit.class::isInstance).singleElement()
                .extracting(hit -> ((PlayEvent.Hit) hit).kind()).isEqualTo(GizmoKind.PORTAL);
    }

    @Test
    void aBallLyingWhereTheBallWouldComeOutBlocksTheWayOutToo() {
        Board board = board();
        portal(board, "A", 4, 10, 2);
        portal(board, "Z", 14, 10, 3);
        board.set("A", Setting.Pair.with("Z"));
        board.addBall("Still", 13.6, 10.6, 0, 0);   // overlapping the spot left of Z's mouth where B would appear
        aimAt(board, 4, 10, 2);
        play(board);
        assertBouncedOffTheMouth(board, 4, 10, 2);
        assertThat(board.ball("Still").orElseThrow().position()).isEqualTo(new Vect(13.6, 10.6));
    }

    @Test
    void aPairWhoseMouthFacesTheOuterWallIsBlocked() {
        Board board = board();
        portal(board, "A", 4, 10, 1);
        portal(board, "Z", 19, 5, 1);   // its mouth on the right wall: no room for a ball
        board.set("A", Setting.Pair.with("Z"));
        aimAt(board, 4, 10, 1);
        play(board);
        assertBouncedOffTheMouth(board, 4, 10, 1);
    }

    @Test
    void aPortalWithoutAPairIsAWall() {
        Board board = board();
        portal(board, "A", 4, 10, 3);
        aimAt(board, 4, 10, 3);
        play(board);
        assertBouncedOffTheMouth(board, 4, 10, 3);
    }

    @Test
    void theOtherSidesOfAPairedPortalAreWalls() {
        Board board = board();
        portal(board, "A", 4, 10, 1);   // mouth right; the ball comes at its top
        portal(board, "Z", 14, 10, 0);
        board.set("A", Setting.Pair.with("Z"));
        aimAt(board, 4, 10, 0);
        play(board);
        assertBouncedOffTheMouth(board, 4, 10, 0);
    }

    @Test
    void aPairIsMutualAndOnePortalHasOneAndDeletionOrANewPairLeavesTheOldPartnerWithout() {
        Board board = board();
        portal(board, "A", 1, 1, 0);
        portal(board, "Z", 5, 1, 0);
        portal(board, "Q", 9, 1, 0);
        board.set("A", Setting.Pair.with("Z"));
        assertThat(pair(board, "Z")).contains("A");
        board.set("Q", Setting.Pair.with("Z"));
        assertThat(pair(board, "A")).as("Z left it for Q").isEmpty();
        assertThat(pair(board, "Q")).contains("Z");
        board.delete("Q");
        assertThat(pair(board, "Z")).isEmpty();
        board.addGizmo(GizmoKind.SQUARE, "S", 12, 12);
        assertThatThrownBy(() -> board.set("A", Setting.Pair.with("S"))).isInstanceOf(BoardEditException.class)
                .hasMessage("only portals are paired: S is a square");
        assertThatThrownBy(() -> board.set("A", Setting.Pair.with("A"))).isInstanceOf(BoardEditException.class)
                .hasMessage("a portal cannot be paired with itself: A");
        board.set("A", Setting.Pair.with("Z"));
        Board copy = board.copy();
        assertThat(pair(copy, "A")).contains("Z");
        board.set("Z", new Setting.Pair(Optional.empty()));
        assertThat(pair(board, "A")).isEmpty();
        assertThat(pair(copy, "A")).as("the copy keeps its own pair").contains("Z");
    }

    private static java.util.Optional<String> pair(Board board, String portal) {
        return ((PortalView) board.gizmo(portal).orElseThrow()).pair();
    }
}
