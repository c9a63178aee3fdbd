package gizmoball.model.loop;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.LoopViews;
import gizmoball.model.gizmo.GizmoKind;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import physics.Vect;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The schedule's bookkeeping against asking everything afresh: after any sequence of collisions, each followed by
 * new velocities for the balls involved (what stage 4 does), and balls carried away now and then and filed afresh,
 * it names the same next collision at the same time.
 */
class CollisionScheduleTest {

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {31, 32, 33, 34, 35, 36, 37, 38})
    void knowsTheSameNextCollisionAsAFreshSchedule(long seed) {
        Random random = new Random(seed);
        Board board = new Board();
        for (int i = 0; i < 25; i++) {
            try {
                board.addGizmo(new GizmoKind[] {GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE}[random.nextInt(3)],
                        "G" + i, random.nextInt(20), random.nextInt(20));
            } catch (BoardEditException refused) {
                // taken cell: one gizmo fewer
            }
        }
        for (int i = 0; i < 30; i++) {
            try {
                board.addBall("B" + i, 0.25 + 19.5 * random.nextDouble(), 0.25 + 19.5 * random.nextDouble(),
                        60 * random.nextGaussian(), 60 * random.nextGaussian());
            } catch (BoardEditException refused) {
                // overlapping: one ball fewer
            }
        }
        List<Ball> free = new ArrayList<>(LoopViews.of(board).balls());
        CollisionDetector detector = new CollisionDetector(LoopViews.of(board), new FinishedBalls(),
                LoopSettings.STANDARD);
        Motions motions = new Motions();
        CollisionSchedule schedule = new CollisionSchedule(detector, new BallGrid(), motions, LoopSettings.STANDARD);
        double tick = 0.25;
        schedule.file(free, 0, tick);
        double elapsed = 0;
        int step = 0;
        for (; step < 200 && elapsed < tick; step++) {
            Collision kept = schedule.next(free, elapsed, tick - elapsed);
            int[] keptSlots = free.stream().mapToInt(Ball::slot).toArray();
            CollisionSchedule afresh = new CollisionSchedule(detector, new BallGrid(), new Motions(),
                    LoopSettings.STANDARD);
            afresh.file(free, elapsed, tick);
            Collision fresh = afresh.next(free, elapsed, tick - elapsed);
            afresh.unfile();
            for (int i = 0; i < free.size(); i++) {
                free.get(i).file(motions, keptSlots[i]);   // a ball is filed in one schedule: the kept one
            }
            String where = "seed " + seed + " step " + step;
            if (fresh == null) {
                assertThat(kept).as(where).isNull();
                break;
            }
            assertThat(kept).as(where).isNotNull();
            assertThat(kept.time()).as(where).isCloseTo(fresh.time(), within(1e-12));
            for (Ball ball : free) {
                ball.advance(kept.time());
            }
            elapsed += kept.time();
            changeVelocity(kept.ball(), random, schedule, elapsed);
            if (kept.contact() instanceof Contact.OtherBall other) {
                changeVelocity(other.other(), random, schedule, elapsed);
            }
            if (step % 3 == 1) {
                carryAway(free.get(random.nextInt(free.size())), free, random, schedule, elapsed);
            }
            findsEachNearBallOnce(free.get(random.nextInt(free.size())), free, schedule, elapsed);
        }
        assertThat(step).as("collisions compared").isGreaterThan(50);
    }

    /**
     * Collisions within {@link Tolerances#TIME_TIE} of the earliest are near-ties: of them the first circle in board
     * order is taken, else the first, whatever comes later. Ball A meets the left wall 0.5 tie after the earliest, ball
     * C at the earliest; ball B meets a circle bumper {@code circleAfter} ties after it. A search that let each offer
     * in board order displace the best by a tie's width took C when B was 1.4 ties late (A, displaced by B, displaced
     * by C).
     */
    @ParameterizedTest(name = "circle {0} ties after the earliest")
    @ValueSource(doubles = {0.6, 1.4, 3})
    void takesTheFirstCircleAmongTheNearTiesOfTheEarliest(double circleAfter) throws BoardEditException {
        double tie = Tolerances.TIME_TIE;
        double earliest = 1;   // s, at 1 L/s: each ball starts this far, plus its ties, from what it meets
        Board board = new Board();
        board.addGizmo(GizmoKind.CIRCLE, "Bumper", 10, 10);
        board.addBall("A", Arena.BALL_RADIUS + earliest + 0.5 * tie, 3, -1, 0);
        board.addBall("B", 10.5, 10 - Arena.BALL_RADIUS - earliest - circleAfter * tie, 0, 1);
        board.addBall("C", Arena.BALL_RADIUS + earliest, 16, -1, 0);
        List<Ball> free = new ArrayList<>(LoopViews.of(board).balls());
        CollisionDetector detector = new CollisionDetector(LoopViews.of(board), new FinishedBalls(),
                LoopSettings.STANDARD);
        CollisionSchedule schedule = new CollisionSchedule(detector, new BallGrid(), new Motions(),
                LoopSettings.STANDARD);
        schedule.file(free, 0, 2);

        Collision next = schedule.next(free, 0, 2);

        String expected = circleAfter <= 1 ? "B" : "A";
        assertThat(next.ball().name()).isEqualTo(expected);
        assertThat(next.time()).isCloseTo(earliest + (circleAfter <= 1 ? circleAfter : 0.5) * tie, within(tie / 10));
    }

    /**
     * The ball goes where its motion could not take it (as an absorber firing the ball it just caught, or a portal,
     * moves it): to a free place, drawn at random, near another ball, so that the pair meets soon if it is found.
     */
    private static void carryAway(Ball ball, List<Ball> free, Random random, CollisionSchedule schedule,
                                  double elapsed) {
        for (int attempt = 0; attempt < 100; attempt++) {
            Ball near = free.get(random.nextInt(free.size()));
            double angle = 2 * Math.PI * random.nextDouble();
            double x = near.x() + 3 * Arena.BALL_RADIUS * Math.cos(angle);
            double y = near.y() + 3 * Arena.BALL_RADIUS * Math.sin(angle);
            if (near != ball && x > 1 && x < Arena.SIZE - 1 && y > 1 && y < Arena.SIZE - 1
                    && free.stream().allMatch(other -> other == ball
                            || Math.hypot(other.x() - x, other.y() - y) > 2.5 * Arena.BALL_RADIUS)) {
                schedule.forget(ball);
                ball.moveTo(new Vect(x, y));
                schedule.refile(ball, elapsed);
                return;
            }
        }
    }

    /** The balls filed near a ball are those within the distance along x and y, each once (a cluster's balls). */
    private static void findsEachNearBallOnce(Ball ball, List<Ball> free, CollisionSchedule schedule,
                                              double elapsed) {
        double within = 1.5;
        List<Ball> found = new ArrayList<>();
        schedule.filedNear(ball, within, elapsed, found);
        List<Ball> expected = free.stream()
                .filter(other -> Math.abs(other.x() - ball.x()) <= within && Math.abs(other.y() - ball.y()) <= within)
                .toList();
        assertThat(found).as("near " + ball).doesNotHaveDuplicates().containsAll(expected);
    }

    /** Reversed (and rescaled), the velocity leads away from what the ball touches, as a bounce's would. */
    private static void changeVelocity(Ball ball, Random random, CollisionSchedule schedule, double elapsed) {
        ball.setVelocity(ball.velocity().times(-(0.5 + random.nextDouble())));
        schedule.forget(ball);
        schedule.sped(ball, elapsed);
    }
}
