package gizmoball.lab;

import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Action;
import gizmoball.model.loop.BallView;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.SplittableRandom;
import physics.Vect;

/**
 * A reactive flipper player: it watches each ball on its flight (ballistic, under the board's gravity) and, when it
 * sees a ball that will be in a flipper's swept area by the time its press could swing the flipper there, presses
 * that flipper's key after its reaction time, holds the flipper up a moment (to shoot or cradle the ball) and lets
 * it down. Now and then it reacts late or not at all, as people do. It launches as the {@link IdlePlayer} does.
 *
 * <p>It uses the board's public API only: the flippers and their keys from the key bindings (a key whose press
 * raises a flipper), the balls' positions and velocities, {@link Board#keyDown} and {@link Board#keyUp}. Each tick
 * costs a few multiplications per ball and flipper and allocates nothing of its own.
 */
public final class AutoPlayer implements Player {
    /** Ticks from seeing a ball to pressing the key: a reaction of 50 to 100 ms at 60 ticks a second. */
    static final int MIN_REACTION_TICKS = 3;
    static final int MAX_REACTION_TICKS = 6;
    /** Ticks a flipper takes to swing up (90 degrees at 1080 degrees a second, 1/12 s), and one to spare. */
    static final int SWING_TICKS = 6;
    /** The chance that a press comes late, and by how many ticks at most. */
    static final double LATE_CHANCE = 0.08;
    static final int MAX_LATE_TICKS = 5;
    /** The chance that a ball in reach is missed altogether: the key stays up while it passes. */
    static final double MISS_CHANCE = 0.04;
    static final int MISS_TICKS = 20;
    /** Ticks a flipper is held up: long enough to shoot or cradle the ball, short enough not to hold it for ever. */
    static final int MIN_HOLD_TICKS = 6;
    static final int MAX_HOLD_TICKS = 15;
    /** Ticks after a release before the next press: the flipper falls back first. */
    static final int SETTLE_TICKS = 4;

    private final Launcher launcher;
    private final List<FlipperKey> keys = new ArrayList<>();
    private final SplittableRandom random;
    private final double dt;
    private final double gravity;

    /** For {@code board}, played in ticks of {@code dt} seconds. */
    public AutoPlayer(Board board, double dt, SplittableRandom random) {
        this.launcher = new Launcher(board, dt, random);
        this.random = random;
        this.dt = dt;
        this.gravity = board.gravity();
        // Each flipper goes with the first key whose press raises it; a key raising several moves them together.
        Map<Integer, List<FlipperReach>> reachesByKey = new LinkedHashMap<>();
        List<String> taken = new ArrayList<>();
        for (KeyBinding binding : board.keyBindings()) {
            if (binding.edge() == KeyEdge.DOWN && !taken.contains(binding.gizmo())
                    && binding.order().action().orElse(Action.RAISE) == Action.RAISE) {
                Optional<FlipperReach> reach = board.gizmo(binding.gizmo()).flatMap(FlipperReach::of);
                if (reach.isPresent()) {
                    taken.add(binding.gizmo());
                    reachesByKey.computeIfAbsent(binding.keyCode(), k -> new ArrayList<>()).add(reach.get());
                }
            }
        }
        reachesByKey.forEach((code, reaches) -> keys.add(new FlipperKey(code, reaches.toArray(FlipperReach[]::new))));
    }

    @Override
    public void beforeTick(Board board) {
        launcher.beforeTick(board);
        if (keys.isEmpty()) {
            return;
        }
        List<BallView> balls = board.balls();
        for (FlipperKey key : keys) {
            key.beforeTick(board, balls);
        }
    }

    /** A key that raises one or more flippers, and what the player is doing with it. */
    private final class FlipperKey {
        private final int keyCode;
        private final FlipperReach[] reaches;
        private boolean held;
        /** While up: the tick to let go. While down with a press coming: the tick to press, else -1. */
        private long releaseAt;
        private long pressAt = -1;
        /** The next press may not come before this tick. */
        private long readyAt;
        /** The reaction time of the next press, drawn when the last one was done with. */
        private int reaction = drawReaction();

        FlipperKey(int keyCode, FlipperReach[] reaches) {
            this.keyCode = keyCode;
            this.reaches = reaches;
        }

        void beforeTick(Board board, List<BallView> balls) {
            long now = board.ticks();
            if (held) {
                if (now >= releaseAt) {
                    board.keyUp(keyCode);
                    held = false;
                    readyAt = now + SETTLE_TICKS;
                }
            } else if (pressAt >= 0) {
                if (now >= pressAt) {
                    board.keyDown(keyCode);
                    held = true;
                    pressAt = -1;
                    releaseAt = now + MIN_HOLD_TICKS + random.nextInt(MAX_HOLD_TICKS - MIN_HOLD_TICKS + 1);
                    reaction = drawReaction();
                }
            } else if (now >= readyAt && anyBallComingIntoReach(balls)) {
                decide(now);
            }
        }

        /** A ball is seen coming: the press is planned after the reaction time, later, or not at all. */
        private void decide(long now) {
            double chance = random.nextDouble();
            if (chance < MISS_CHANCE) {
                readyAt = now + MISS_TICKS;
            } else if (chance < MISS_CHANCE + LATE_CHANCE) {
                pressAt = now + reaction + 1 + random.nextInt(MAX_LATE_TICKS);
            } else {
                pressAt = now + reaction;
            }
        }

        /**
         * Whether a ball flying free would be in a flipper's swept area while the flipper swings up, were the key
         * pressed after the reaction time: at each tick from then until the swing is over.
         */
        private boolean anyBallComingIntoReach(List<BallView> balls) {
            for (BallView ball : balls) {
                if (ball.isCaptured()) {
                    continue;
                }
                Vect p = ball.position();
                Vect v = ball.velocity();
                for (int tick = reaction; tick <= reaction + SWING_TICKS; tick++) {
                    double t = tick * dt;
                    double x = p.x() + v.x() * t;
                    double y = p.y() + v.y() * t + gravity * t * t / 2;
                    for (FlipperReach reach : reaches) {
                        if (reach.reaches(x, y)) {
                            return true;
                        }
                    }
                }
            }
            return false;
        }

        private int drawReaction() {
            return MIN_REACTION_TICKS + random.nextInt(MAX_REACTION_TICKS - MIN_REACTION_TICKS + 1);
        }
    }
}
