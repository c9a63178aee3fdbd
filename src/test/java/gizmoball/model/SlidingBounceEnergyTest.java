package gizmoball.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.PlayEvent;
import gizmoball.model.loop.Struck;

import org.junit.jupiter.api.Test;

import physics.Vect;

/**
 * A ball sliding on a slope into a wall at its foot, bouncing back up and sliding down again (docs/design.md,
 * "Energy drift"). Between bounces the integration keeps the shadow energy S = |v + g dt/2|^2/2 - g . p exactly
 * (v the velocity of the tick just ended): gravity's kick pressed into the slope is removed, the rest of it is
 * gravity along the slope, and the straight move stays on it. A bounce part-way through a tick moves S by up to
 * g dt |v_n|; unless that is corrected, the bounces random-walk the energy, and a ball at the foot of a slope can
 * lock onto a phase of the tick that feeds it what friction takes: balls on the stress board bounced in such notches
 * at 1 L/s for minutes, never coming to rest.
 */
class SlidingBounceEnergyTest {
    private static final double DT = Board.DEFAULT_TICK;
    private static final double R = 0.25;

    /**
     * A triangle turned three times (its slope x - y + 5 = 0 from (5, 10) down to (6, 11)) beside a square (its left wall
     * x = 6): the notch where stress.txt's balls bounced. The ball starts at rest touching the slope half-way up.
     */
    private static Board notch(double mu, double mu2) {
        return notch(mu, mu2, 5.3);
    }

    /** The same, the ball touching the slope at the point (at, at + 5). */
    private static Board notch(double mu, double mu2, double at) {
        Board board = new Board();
        board.setFriction(mu, mu2);
        board.addGizmo(GizmoKind.TRIANGLE, "T", 5, 10);
        board.rotate("T");
        board.rotate("T");
        board.rotate("T");
        board.addGizmo(GizmoKind.SQUARE, "S", 6, 10);
        double offset = R / Math.sqrt(2);   // along the slope's normal (1, -1)/sqrt 2
        board.addBall("B", at + offset, at + 5 - offset, 0, 0);
        return board;
    }

    private static double shadowEnergy(Board board) {
        double sum = 0;
        for (BallView ball : board.balls()) {
            Vect g = new Vect(0, board.gravity());
            Vect w = ball.velocity().plus(g.times(DT / 2));
            sum += w.dot(w) / 2 - g.dot(ball.position());
        }
        return sum;
    }

    @Test
    void withoutFrictionEveryBounceKeepsTheShadowEnergy() {
        Board board = notch(0, 0);
        board.tick(DT);   // the first tick finds the slope as a contact
        double start = shadowEnergy(board);
        int bounces = 0;
        double worst = 0;
        for (int i = 0; i < 60 * 60; i++) {
            board.tick(DT);
            bounces += board.lastTick().collisions() > 0 ? 1 : 0;
            worst = Math.max(worst, Math.abs(shadowEnergy(board) - start));
            assertThat(board.ball("B").orElseThrow().position().x()).as("tick %d", i).isLessThan(6 - R + 1e-9);
        }
        assertThat(bounces).as("ticks with a bounce").isGreaterThan(100);
        // Exact in exact arithmetic; what is left is rounding, far below the g dt |v_n| (about 0.1 here) of a bounce.
        assertThat(worst).isLessThan(1e-9 * Math.abs(start));
    }

    /**
     * A second ball lies in the notch, held there by the slope and the wall: the first slides down into it and back
     * up, again and again. Each meeting is solved with everything the two touch at once (a contact cluster); the
     * solve keeps the energy, so the timing of the bounce is corrected as a single bounce's is, along the slope.
     */
    @Test
    void withoutFrictionABallBouncingOffOneHeldInTheNotchKeepsTheShadowEnergy() {
        Board board = notch(0, 0, 5.1);
        board.addBall("H", 6 - R, 6 - R + 5 - R * Math.sqrt(2), 0, 0);
        board.tick(DT);
        double start = shadowEnergy(board);
        int meetings = 0;
        double worst = 0;
        for (int i = 0; i < 60 * 60; i++) {
            board.tick(DT);
            meetings += board.lastTick().events().stream().anyMatch(e -> e instanceof PlayEvent.Hit hit
                    && hit.struck() instanceof Struck.OtherBall) ? 1 : 0;
            worst = Math.max(worst, Math.abs(shadowEnergy(board) - start));
        }
        assertThat(meetings).as("ticks in which the balls met").isGreaterThan(100);
        assertThat(board.ball("H").orElseThrow().position().x()).isCloseTo(6 - R, within(1e-9));
        assertThat(worst).isLessThan(1e-9 * Math.abs(start));
    }

    /**
     * Friction takes energy, but S is not quite the energy: scaling v by f = 1 - (mu + mu2 |v|) dt before the kick
     * moves S by ((f^2 - 1)|v|^2 + 2 (f - 1) v . h)/2 with h = g dt/2, which is positive where a slow ball turns
     * against gravity, and at most (1 - f) |v| |h|. So S may rise by that much in a tick, and by nothing more.
     */
    @Test
    void withFrictionTheBouncesDieAwayAndTheBallSleepsInTheNotch() {
        double mu = 0.5;
        double mu2 = 0.5;
        Board board = notch(mu, mu2);
        board.tick(DT);
        double previous = shadowEnergy(board);
        int tick = 0;
        while (!board.ball("B").orElseThrow().isAsleep() && tick < 60 * 60) {
            double speed = board.ball("B").orElseThrow().velocity().length();
            board.tick(DT);
            tick++;
            double now = shadowEnergy(board);
            double frictionsRise = (mu + mu2 * speed) * DT * speed * board.gravity() * DT / 2;
            assertThat(now).as("shadow energy at tick %d: friction only takes", tick)
                    .isLessThanOrEqualTo(previous + frictionsRise + 1e-9 * Math.abs(previous));
            previous = now;
        }
        assertThat(board.ball("B").orElseThrow().isAsleep()).as("asleep within a minute").isTrue();
        BallView ball = board.ball("B").orElseThrow();
        // At rest touching both: x = 6 - r, and r from the slope's line x - y + 5 = 0.
        assertThat(ball.position().x()).isCloseTo(6 - R, within(1e-6));
        assertThat((ball.position().x() - ball.position().y() + 5) / Math.sqrt(2)).isCloseTo(R, within(1e-6));
    }
}
