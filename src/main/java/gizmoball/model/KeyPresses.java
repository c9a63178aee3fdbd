package gizmoball.model;

import gizmoball.model.game.Game;
import gizmoball.model.game.KeyPress;
import gizmoball.model.game.Nudge;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;
import gizmoball.model.loop.Sleepers;

import java.util.Optional;

import physics.Vect;

/**
 * A key going down or up in play: the game records it with the tick; a nudge key nudges the board, any other drives
 * the gizmos bound to it ({@link Play#keyAction}).
 */
final class KeyPresses {
    private final Registry registry;
    private final Wiring wiring;
    private final Play play;
    private final Sleepers sleepers;
    private final GameSettings settings;
    private final Clock clock;
    private final Game game;

    KeyPresses(Registry registry, Wiring wiring, Play play, Sleepers sleepers, GameSettings settings, Clock clock,
            Game game) {
        this.registry = registry;
        this.wiring = wiring;
        this.play = play;
        this.sleepers = sleepers;
        this.settings = settings;
        this.clock = clock;
        this.game = game;
    }

    void key(int keyCode, KeyEdge edge) {
        game.keyPressed(clock.ticks(), edge == KeyEdge.DOWN ? KeyPress.Motion.DOWN : KeyPress.Motion.UP, keyCode);
        Optional<Nudge.Way> nudge = settings.nudgeWay(keyCode);
        if (nudge.isPresent()) {
            if (edge == KeyEdge.DOWN) {
                nudge(nudge.get());
            }
            return;
        }
        play.keyAction(wiring.keyBindings(), keyCode, edge, clock.time(), game.isTilted());
    }

    /**
     * Every free ball gets the nudge's speed that way, woken if asleep; held balls feel nothing. The nudge counts
     * toward the tilt: one that tilts lowers every flipper and lets go of every plunger's pull.
     */
    private void nudge(Nudge.Way way) {
        double speed = settings.rules().nudge().orElseThrow().speed();
        Vect push = new Vect(way.dx() * speed, way.dy() * speed);
        sleepers.wakeWithin(-Arena.SIZE, -Arena.SIZE, 2 * Arena.SIZE, 2 * Arena.SIZE);
        for (Ball ball : registry.balls()) {
            if (!ball.isCaptured()) {
                ball.setVelocity(ball.velocity().plus(push));
            }
        }
        if (game.nudged(clock.ticks())) {
            play.tilt();
        }
    }
}
