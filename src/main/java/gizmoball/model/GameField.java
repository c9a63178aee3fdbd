package gizmoball.model;

import gizmoball.model.game.GameRules;
import gizmoball.model.game.Playfield;
import gizmoball.model.gizmo.Absorber;
import gizmoball.model.gizmo.GizmoBase;
import gizmoball.model.loop.Arena;
import gizmoball.model.loop.Ball;

import physics.Vect;

/** The board as its game sees it: the rules, and the balls, which a game may take off when they drain. */
final class GameField implements Playfield {
    private final Board board;
    private final Registry registry;
    private final Play play;

    GameField(Board board, Registry registry, Play play) {
        this.board = board;
        this.registry = registry;
        this.play = play;
    }

    @Override
    public GameRules rules() {
        return board.gameRules();
    }

    @Override
    public int ballCount() {
        return registry.balls().size();
    }

    @Override
    public void removeBall(String ball) {
        registry.remove(registry.ball(ball));
    }

    @Override
    public boolean serveNextBall() {
        for (GizmoBase gizmo : registry.gizmos()) {
            if (gizmo instanceof Absorber absorber && board.gameRules().isDrain(absorber.name())) {
                String name = play.freshBallName();
                Vect at = absorber.holdingPosition(Arena.BALL_RADIUS);
                Ball ball = new Ball(name, at, Vect.ZERO);
                registry.add(ball);
                play.capture(ball, absorber);
                return true;
            }
        }
        return false;
    }
}
