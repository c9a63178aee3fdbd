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

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The schedule's bookkeeping against asking everything afresh: after any sequence of collisions, each followed by
 * new velocities for the balls involved (what stage 4 does), it names the same next collision at the same time.
 */
class CollisionScheduleTest {

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {31, 32, 33, 34})
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
        CollisionSchedule schedule = new CollisionSchedule(detector, new BallGrid(), LoopSettings.STANDARD);
        schedule.file(free, 0);
        double tick = 0.25;
        double elapsed = 0;
        int step = 0;
        for (; step < 200 && elapsed < tick; step++) {
            Collision kept = schedule.next(free, elapsed, tick - elapsed);
            CollisionSchedule afresh = new CollisionSchedule(detector, new BallGrid(), LoopSettings.STANDARD);
            afresh.file(free, elapsed);
            Collision fresh = afresh.next(free, elapsed, tick - elapsed);
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
            changeVelocity(kept.ball(), random, schedule);
            if (kept.contact() instanceof Contact.OtherBall other) {
                changeVelocity(other.other(), random, schedule);
            }
        }
        assertThat(step).as("collisions compared").isGreaterThan(50);
    }

    /** Reversed (and rescaled), the velocity leads away from what the ball touches, as a bounce's would. */
    private static void changeVelocity(Ball ball, Random random, CollisionSchedule schedule) {
        ball.setVelocity(ball.velocity().times(-(0.5 + random.nextDouble())));
        schedule.forget(ball);
        schedule.sped(ball);
    }
}
