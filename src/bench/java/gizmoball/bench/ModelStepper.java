package gizmoball.bench;

import gizmoball.model.BenchSwitches;
import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;

import java.util.ArrayList;
import java.util.List;

/** The model's own loop, in the mode the method names. */
final class ModelStepper implements Stepper {

    private final Board board;

    ModelStepper(Board board, Loop loop, boolean spatialIndex) {
        this.board = board;
        BenchSwitches.configure(board, loop.modelMode(), spatialIndex);
    }

    @Override
    public void tick(double dt) {
        board.tick(dt);
    }

    @Override
    public void keyDown(int keyCode) {
        board.keyDown(keyCode);
    }

    @Override
    public void keyUp(int keyCode) {
        board.keyUp(keyCode);
    }

    @Override
    public List<BallState> balls() {
        List<BallState> balls = new ArrayList<>();
        for (BallView b : board.balls()) {
            balls.add(new BallState(b.position(), b.velocity(), b.radius(), b.isCaptured()));
        }
        return balls;
    }

    @Override
    public List<Gizmo> gizmos() {
        return board.gizmos();
    }

    @Override
    public double energy() {
        return board.energy();
    }

    @Override
    public boolean checksModelInvariants() {
        return true;
    }

    @Override
    public boolean modelInvariantsHold() {
        return Invariants.violations(board).isEmpty();
    }
}
