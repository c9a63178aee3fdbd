package gizmoball.model;

import gizmoball.model.game.GameRules;
import gizmoball.model.game.Playfield;
import gizmoball.model.gizmo.BallHolder;
import gizmoball.model.gizmo.GizmoBase;
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
                || registry.gizmo(absorber) instanceof BallHolder holder && holder.plunger().isPresent();
    }

    @Override
    public void removeBall(String ball) {
        registry.remove(registry.ball(ball));
    }

    @Override
    public boolean serve(Optional<String> drained) {
        Optional<GizmoBase> holder = drained.flatMap(ball -> holders().filter(h -> h.held().contains(ball))
                .findFirst());
        Optional<GizmoBase> launcher = holders().filter(h -> h.plunger().isPresent()).findFirst()
                .or(() -> holder)
                .or(() -> holders().filter(h -> settings.rules().isDrain(h.name())).findFirst());
        if (launcher.isEmpty()) {
            return false;
        }
        Ball ball = drained.map(registry::ball).orElseGet(() -> {
            Vect holding = ((BallHolder) launcher.get()).holdingPosition(Arena.BALL_RADIUS);
            Ball fresh = new Ball(registry.freshBallName(), holding, Vect.ZERO);
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

    /** The gizmos that hold balls (absorbers), in board order: where a served ball can wait to be launched. */
    private Stream<GizmoBase> holders() {
        return registry.gizmos().stream().filter(g -> g instanceof BallHolder);
    }
}
