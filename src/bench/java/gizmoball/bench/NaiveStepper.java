package gizmoball.bench;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import physics.Vect;

import java.util.ArrayList;
import java.util.List;

/**
 * The baseline people write first, for comparison only: each tick apply friction and gravity, move every
 * ball by v dt, then push each ball out of whatever it overlaps (walls, bumpers, flippers at their current
 * angle, other balls) along the nearest surface's normal and reflect its velocity if it was moving in.
 * Flippers swing because the scene's board, emptied of its balls, is ticked alongside; their surface speed
 * is ignored. No collision times: fast balls tunnel, and overlap is repaired after the fact.
 */
final class NaiveStepper implements Stepper {

    private final Board gizmosOnly;
    private final double gravity;
    private final double mu;
    private final double mu2;
    private final double[] x;
    private final double[] y;
    private final double[] vx;
    private final double[] vy;
    private final double[] radius;

    NaiveStepper(Board scene) {
        List<BallView> balls = scene.balls();
        int n = balls.size();
        x = new double[n];
        y = new double[n];
        vx = new double[n];
        vy = new double[n];
        radius = new double[n];
        gizmosOnly = scene.copy();
        for (int i = 0; i < n; i++) {
            BallView b = balls.get(i);
            x[i] = b.position().x();
            y[i] = b.position().y();
            vx[i] = b.velocity().x();
            vy[i] = b.velocity().y();
            radius[i] = b.radius();
            gizmosOnly.delete(b.name());
        }
        gravity = scene.gravity();
        mu = scene.mu();
        mu2 = scene.mu2();
    }

    @Override
    public void tick(double dt) {
        gizmosOnly.tick(dt);
        List<Gizmo> gizmos = gizmosOnly.gizmos();
        for (int i = 0; i < x.length; i++) {
            double speed = Math.hypot(vx[i], vy[i]);
            double scale = Math.max(0, 1 - mu * dt - mu2 * speed * dt);
            vx[i] *= scale;
            vy[i] = vy[i] * scale + gravity * dt;
            speed = Math.hypot(vx[i], vy[i]);
            if (speed > Board.MAX_SPEED) {
                vx[i] *= Board.MAX_SPEED / speed;
                vy[i] *= Board.MAX_SPEED / speed;
            }
            x[i] += vx[i] * dt;
            y[i] += vy[i] * dt;
        }
        for (int i = 0; i < x.length; i++) {
            resolve(i, new Surfaces.Nearest(x[i], 1, 0), 1.0);
            resolve(i, new Surfaces.Nearest(Board.SIZE - x[i], -1, 0), 1.0);
            resolve(i, new Surfaces.Nearest(y[i], 0, 1), 1.0);
            resolve(i, new Surfaces.Nearest(Board.SIZE - y[i], 0, -1), 1.0);
            for (Gizmo g : gizmos) {
                resolve(i, Surfaces.nearest(g, x[i], y[i]), g.reflectionCoefficient());
            }
        }
        for (int i = 0; i < x.length; i++) {
            for (int j = i + 1; j < x.length; j++) {
                resolveBalls(i, j);
            }
        }
    }

    /** Push ball i out along the normal if it overlaps, and reflect the inward part of its velocity. */
    private void resolve(int i, Surfaces.Nearest s, double coefficient) {
        double overlap = radius[i] - s.distance();
        if (overlap <= 0) {
            return;
        }
        x[i] += s.nx() * overlap;
        y[i] += s.ny() * overlap;
        double inward = vx[i] * s.nx() + vy[i] * s.ny();
        if (inward < 0) {
            vx[i] -= (1 + coefficient) * inward * s.nx();
            vy[i] -= (1 + coefficient) * inward * s.ny();
        }
    }

    /** Equal masses: push both apart by half the overlap each and exchange the closing normal velocity. */
    private void resolveBalls(int i, int j) {
        double dx = x[j] - x[i];
        double dy = y[j] - y[i];
        double d = Math.hypot(dx, dy);
        double overlap = radius[i] + radius[j] - d;
        if (overlap <= 0 || d == 0) {
            return;
        }
        double nx = dx / d;
        double ny = dy / d;
        x[i] -= nx * overlap / 2;
        y[i] -= ny * overlap / 2;
        x[j] += nx * overlap / 2;
        y[j] += ny * overlap / 2;
        double closing = (vx[j] - vx[i]) * nx + (vy[j] - vy[i]) * ny;
        if (closing < 0) {
            vx[i] += closing * nx;
            vy[i] += closing * ny;
            vx[j] -= closing * nx;
            vy[j] -= closing * ny;
        }
    }

    @Override
    public void keyDown(int keyCode) {
        gizmosOnly.keyDown(keyCode);
    }

    @Override
    public void keyUp(int keyCode) {
        gizmosOnly.keyUp(keyCode);
    }

    @Override
    public List<BallState> balls() {
        List<BallState> balls = new ArrayList<>();
        for (int i = 0; i < x.length; i++) {
            balls.add(new BallState(new Vect(x[i], y[i]), new Vect(vx[i], vy[i]), radius[i], false));
        }
        return balls;
    }

    @Override
    public List<Gizmo> gizmos() {
        return gizmosOnly.gizmos();
    }

    @Override
    public double energy() {
        double e = 0;
        for (int i = 0; i < x.length; i++) {
            e += (vx[i] * vx[i] + vy[i] * vy[i]) / 2 + gravity * (Board.SIZE - y[i]);
        }
        return e;
    }

    @Override
    public boolean checksModelInvariants() {
        return false;
    }

    @Override
    public boolean modelInvariantsHold() {
        throw new UnsupportedOperationException("the model's Invariants do not apply to the naive loop's own balls");
    }
}
