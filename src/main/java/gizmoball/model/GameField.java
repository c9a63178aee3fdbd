package gizmoball.model;

import gizmoball.model.game.GameRules;
import gizmoball.model.game.Playfield;
import gizmoball.model.gizmo.Absorber;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;

import java.util.Optional;
import java.util.stream.Stream;

import physics.Vect;

/**
 * The board as its game sees it: the rules, the clock, and the balls, which a game may take off when they drain or
 * serve into the launcher.
 */
final class GameField implements Playfield {
    private final GameSettings settings;
    private final Clock clock;
    private final Registry registry;
    private final Play play;

    GameField(GameSettings settings, Clock clock, Registry registry, Play play) {
        this.settings = settings;
        this.clock = clock;
        this.registry = registry;
        this.play = play;
    }

    @Override
    public GameRules rules() {
        return settings.rules();
    }

    @Override
    public double time() {
        return clock.time();
    }

    @Override
    public int ballCount() {
        return registry.balls().size();
    }

    @Override
    public int freeBallCount() {
        return (int) registry.balls().stream().filter(b -> !b.isCaptured()).count();
    }

    @Override
    public boolean isLauncher(String absorber) {
        return settings.rules().isDrain(absorber)
                || registry.gizmo(absorber) instanceof Absorber a && a.plunger().isPresent();
    }

    @Override
    public void removeBall(String ball) {
        registry.remove(registry.ball(ball));
    }

    @Override
    public boolean serve(Optional<String> drained) {
        Optional<Absorber> holder = drained.flatMap(ball -> absorbers().filter(a -> a.held().contains(ball))
                .findFirst());
        Optional<Absorber> launcher = absorbers().filter(a -> a.plunger().isPresent()).findFirst()
                .or(() -> holder)
                .or(() -> absorbers().filter(a -> settings.rules().isDrain(a.name())).findFirst());
        if (launcher.isEmpty()) {
            return false;
        }
        Ball ball = drained.map(registry::ball).orElseGet(() -> {
            Ball fresh = new Ball(registry.freshBallName(), launcher.get().holdingPosition(Arena.BALL_RADIUS), Vect.ZERO);
            registry.add(fresh);
            return fresh;
        });
        if (holder.isPresent() && holder.get() != launcher.get()) {
            holder.get().letGo(ball.name());
        }
        if (holder.isEmpty() || holder.get() != launcher.get()) {
            play.take(ball, launcher.get());
        }
        return true;
    }

    private Stream<Absorber> absorbers() {
        return registry.gizmos().stream().filter(g -> g instanceof Absorber).map(g -> (Absorber) g);
    }
}
