package gizmoball.model.game;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.offset;
import static org.assertj.core.api.Assertions.tuple;

import gizmoball.model.Board;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.TriggerSource;
import gizmoball.sound.Sounds;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Points, drains, balls per game, game over and the extra ball, on small boards built here (docs/design.md, "The game"). */
class GameTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final int SPACE = KeyEvent.VK_SPACE;

    /** No gravity, no friction: a ball flies straight at its speed, every number below follows from that. */
    private static Board weightless() {
        Board board = new Board();
        board.setGravity(0);
        board.setFriction(0, 0);
        return board;
    }

    private static List<PlayEvent.Hit> hitsOn(Board board, String gizmo, int ticks) {
        List<PlayEvent.Hit> hits = new ArrayList<>();
        for (int t = 0; t < ticks; t++) {
            board.tick(DT);
            board.lastTick().events().stream().filter(e -> e instanceof PlayEvent.Hit).map(e -> (PlayEvent.Hit) e)
                    .filter(h -> h.struck().equals(TriggerSource.gizmo(gizmo))).forEach(hits::add);
        }
        return hits;
    }

    /** A ball meets the circle head-on at {@code speed}: it scores, and clicks, exactly when that is a real impact. */
    @ParameterizedTest(name = "{0} L/s")
    @ValueSource(doubles = {0.25, 0.5, 0.999, 1.0, 1.5, 4, 30})
    void aHitScoresAndIsHeardOnlyFromTheRealImpactSpeedOn(double speed) {
        Board board = weightless();
        board.addGizmo(GizmoKind.CIRCLE, "C", 10, 10);
        // Centre level with the circle's, 1 L from touching it; it arrives within 1 / speed s.
        board.addBall("B", 10.5 - 0.5 - Board.BALL_RADIUS - 1, 10.5, speed, 0);

        List<PlayEvent.Hit> hits = hitsOn(board, "C", (int) Math.ceil(1 / speed / DT) + 2);

        assertThat(hits).hasSize(1);
        assertThat(hits.get(0).speed()).isCloseTo(speed, offset(1e-9));
        boolean real = speed >= PlayEvent.Hit.REAL_IMPACT_SPEED;
        assertThat(board.game().score()).isEqualTo(real ? Points.defaultFor(GizmoKind.CIRCLE) : 0);
        assertThat(board.game().scoringHits()).hasSize(real ? 1 : 0);
        assertThat(Sounds.cueFor(hits.get(0))).as("heard").isEqualTo(real ? Sounds.gizmoHit(GizmoKind.CIRCLE, speed)
                : Optional.empty());
    }

    /** Rolling is no hit: a ball rolls on a row of squares, across every seam between them, and scores nothing. */
    @Test
    void aBallRollingAlongARowOfBumpersScoresNothing() {
        Board board = new Board();
        board.setFriction(0, 0);
        for (int x = 1; x < 19; x++) {
            board.addGizmo(GizmoKind.SQUARE, "S" + x, x, 10);
        }
        board.addBall("B", 1.5, 10 - Board.BALL_RADIUS, 6, 0);

        for (int t = 0; t < 150; t++) {
            board.tick(DT);
        }

        assertThat(board.ball("B").orElseThrow().position().x()).as("rolled over 14 seams").isGreaterThan(16);
        assertThat(board.game().scoringHits()).isEmpty();
        assertThat(board.game().score()).isZero();
    }

    /**
     * The bottom row is the drain and launcher; the ball flies straight up into a square, straight back down into the
     * drain, and is launched again: each ball scores the square's points once, and the game ends with the last.
     */
    private static Board launcherUnderASquare(int ballsPerGame) {
        Board board = weightless();
        board.addAbsorber("A", 0, 19, 20, 20);
        board.addGizmo(GizmoKind.SQUARE, "S", 19, 2);
        board.addBall("B", 19.75, 19.75, 0, 0);
        board.bindKey(SPACE, KeyEdge.DOWN, "A");
        board.setDrain("A", true);
        board.setBallsPerGame(ballsPerGame);
        board.setPoints("S", 125);
        return board;
    }

    /** Up 15.5 L (from the absorber's top to the square's face) and back, at the launch speed. */
    private static final int TICKS_THERE_AND_BACK = (int) Math.ceil(2 * 15.5 / Board.ABSORBER_LAUNCH_SPEED / DT);

    /** Presses Space, plays until the ball is back in an absorber (or gone), and returns how many ticks that took. */
    private static int launchAndWait(Board board) {
        board.keyDown(SPACE);
        board.keyUp(SPACE);
        int drains = board.game().drains().size();
        for (int t = 1; t <= 2 * TICKS_THERE_AND_BACK; t++) {
            board.tick(DT);
            if (board.game().drains().size() > drains) {
                return t;
            }
        }
        throw new AssertionError("the ball did not drain within " + 2 * TICKS_THERE_AND_BACK + " ticks");
    }

    @Test
    void eachDrainLosesABallTheNextWaitsInTheDrainAndTheLastEndsTheGame() {
        Board board = launcherUnderASquare(3);
        assertThat(board.game().isGame()).isTrue();
        assertThat(board.game().ballsLeft()).isEqualTo(3);

        for (int ball = 1; ball <= 3; ball++) {
            int ticks = launchAndWait(board);

            assertThat(ticks).isBetween(TICKS_THERE_AND_BACK - 1, TICKS_THERE_AND_BACK + 1);
            assertThat(board.game().score()).isEqualTo(125L * ball);
            assertThat(board.game().ballsLeft()).isEqualTo(3 - ball);
            assertThat(board.game().isOver()).isEqualTo(ball == 3);
            assertThat(board.balls()).hasSize(ball == 3 ? 0 : 1);
        }
        List<Drain> drains = board.game().drains();
        assertThat(drains).extracting(Drain::ball).containsOnly("B");
        assertThat(drains).extracting(Drain::absorber).containsOnly("A");
        assertThat(drains).extracting(Drain::tick).isSorted();
        assertThat(board.game().scoringHits()).extracting(ScoringHit::gizmo, ScoringHit::points)
                .containsExactly(tuple("S", 125), tuple("S", 125),
                        tuple("S", 125));
    }

    @Test
    void afterTheGameIsOverNothingMoreScoresOrDrains() {
        Board board = launcherUnderASquare(1);
        launchAndWait(board);
        assertThat(board.game().isOver()).isTrue();

        board.keyDown(SPACE);
        for (int t = 0; t < 3 * TICKS_THERE_AND_BACK; t++) {
            board.tick(DT);
        }

        assertThat(board.game().score()).isEqualTo(125);
        assertThat(board.game().drains()).hasSize(1);
        assertThat(board.game().ballsLeft()).isZero();
    }

    @Test
    void reachingTheExtraBallScoreGivesOneMoreBallOnce() {
        Board board = launcherUnderASquare(2);
        board.setExtraBallAt(OptionalLong.of(250));

        int launches = 0;
        while (!board.game().isOver()) {
            launchAndWait(board);
            launches++;
            assertThat(launches).as("launches").isLessThanOrEqualTo(3);
        }

        // Two balls, and one more for reaching 250 with the second: 3 x 125; no second extra ball at 500.
        assertThat(launches).isEqualTo(3);
        assertThat(board.game().score()).isEqualTo(375);
        assertThat(board.game().extraBallTick()).hasValue(board.game().scoringHits().get(1).tick());
    }

    @Test
    void withSeveralBallsOnTheBoardEachDrainedOneLeavesItWhenNoneIsToComeAndTheLastEndsTheGame() {
        Board board = weightless();
        board.addAbsorber("A", 0, 19, 20, 20);
        board.setDrain("A", true);
        board.setBallsPerGame(1);
        board.addBall("B1", 5, 15, 0, 10);
        board.addBall("B2", 10, 12, 0, 10);
        assertThat(board.game().ballsLeft()).as("more on the board than a game has").isEqualTo(2);

        for (int t = 0; t < 40; t++) {
            board.tick(DT);
        }
        assertThat(board.game().drains()).extracting(Drain::ball).containsExactly("B1");
        assertThat(board.balls()).extracting(b -> b.name()).containsExactly("B2");
        assertThat(board.game().isOver()).isFalse();
        for (int t = 0; t < 40; t++) {
            board.tick(DT);
        }

        assertThat(board.game().drains()).extracting(Drain::ball).containsExactly("B1", "B2");
        assertThat(board.game().isOver()).isTrue();
        assertThat(board.game().ballsLeft()).isZero();
    }

    @Test
    void aBoardWithoutADrainIsASandboxThatScoresAndNeverEnds() {
        Board board = launcherUnderASquare(1);
        board.setDrain("A", false);
        assertThat(board.game().isGame()).isFalse();

        for (int launch = 0; launch < 3; launch++) {
            board.keyDown(SPACE);
            for (int t = 0; t < TICKS_THERE_AND_BACK + 2; t++) {
                board.tick(DT);
            }
        }

        assertThat(board.game().score()).isEqualTo(3 * 125);
        assertThat(board.game().drains()).isEmpty();
        assertThat(board.game().isOver()).isFalse();
        assertThat(board.balls()).hasSize(1);
    }

    @Test
    void aCopyGoesOnWithTheGameAndClearingStartsAfresh() {
        Board board = launcherUnderASquare(2);
        launchAndWait(board);
        Board copy = board.copy();

        assertThat(copy.game().score()).isEqualTo(125);
        assertThat(copy.game().ballsLeft()).isEqualTo(1);
        assertThat(copy.ticks()).isEqualTo(board.ticks());
        launchAndWait(copy);
        assertThat(copy.game().isOver()).isTrue();
        assertThat(board.game().isOver()).isFalse();

        board.clear();
        assertThat(board.game().score()).isZero();
        assertThat(board.ticks()).isZero();
        assertThat(board.gameRules()).isEqualTo(GameRules.DEFAULT);
    }

    /**
     * A game lists its first {@link Game#LISTED_SCORING_HITS} scoring hits and counts the rest, so that a board that
     * scores all the time keeps no growing list: 18 balls, each between two squares 1 L apart at 100 L/s, score
     * 3 1/3 hits a tick each, every hit at the score of a square.
     */
    @Test
    void aGameListsItsFirstScoringHitsAndCountsTheRest() {
        Board board = weightless();
        for (int row = 1; row <= 18; row++) {
            board.addGizmo(GizmoKind.SQUARE, "L" + row, 5, row);
            board.addGizmo(GizmoKind.SQUARE, "R" + row, 7, row);
            board.addBall("B" + row, 6.5, row + 0.5, 100, 0);
        }
        int points = Points.defaultFor(GizmoKind.SQUARE);

        while (board.game().score() / points <= Game.LISTED_SCORING_HITS + 1_000) {
            board.tick(DT);
        }

        long hits = board.game().score() / points;
        assertThat(board.game().scoringHits()).hasSize(Game.LISTED_SCORING_HITS);
        assertThat(board.game().unlistedScoringHits()).isEqualTo(hits - Game.LISTED_SCORING_HITS);
        assertThat(board.game().scoringHits().get(Game.LISTED_SCORING_HITS - 1).tick())
                .as("the last listed is one of the first hundred thousand, scored before the end")
                .isLessThan(board.ticks());
        Board copy = board.copy();
        assertThat(copy.game().unlistedScoringHits()).as("a copy goes on with the count")
                .isEqualTo(board.game().unlistedScoringHits());
    }
}
