package gizmoball.model.loop;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import physics.Vect;

/**
 * Keeps the energy of elastic bounces (docs/design.md, "Failure modes": energy drift). In free flight the
 * integration (gravity, then a straight move) keeps the shadow energy |u|^2/2 - g . p exactly, u being the velocity
 * half a gravity kick back; an elastic bounce part-way through a tick moves it by up to g dt |v| either way, and
 * many such bounces would random-walk the energy. So the balls whose collisions in a tick were all elastic (with
 * still shapes of coefficient 1 or with each other) get the normal component of their last bounce adjusted at the
 * end of the tick to keep it; their tangential velocity is never touched. One per tick.
 */
final class ShadowEnergy {
    private final Vect gravity;
    private final double dt;
    private final Map<Ball, Double> atStart;
    /** The normal of each ball's last elastic bounce, in order of first bounce (runs stay bit-identical). */
    private final Map<Ball, Vect> elasticNormals;
    private final Set<Ball> lost;
    private final List<List<Ball>> pairs = new ArrayList<>();

    /** For a tick of {@code balls} balls: the books are sized for all of them, so a tick never regrows them. */
    ShadowEnergy(Vect gravity, double dt, int balls) {
        this.gravity = gravity;
        this.dt = dt;
        int capacity = 2 * balls + 16;
        atStart = new HashMap<>(capacity);
        elasticNormals = new LinkedHashMap<>(capacity);
        lost = new HashSet<>(capacity);
    }

    /** After stage 1: right after the gravity kick, u = v - g dt/2. */
    void start(Ball ball) {
        Vect u = ball.velocity().minus(gravity.times(dt / 2));
        atStart.put(ball, u.dot(u) / 2 - gravity.dot(ball.position()));
    }

    /** The ball lost energy this tick (a lossy surface, a rest, a capture, a flipper): it is left alone. */
    void lost(Ball ball) {
        lost.add(ball);
    }

    /** A bounce with the given normal (from the surface to the ball). */
    void bounced(Ball ball, Vect normal, boolean elastic) {
        if (elastic) {
            elasticNormals.put(ball, normal);
        } else {
            lost.add(ball);
        }
    }

    /** Two balls bounced off each other: their energy is kept together, not each one's. */
    void met(Ball ball, Ball other) {
        pairs.add(List.of(ball, other));
    }

    /**
     * Adjusts each group of balls that met each other (or a ball alone). Ball-ball collisions conserve a group's
     * total, so the group shares one correction: each velocity moves by lambda along the normal of the ball's last
     * bounce (opposite normals for a pair, so momentum is kept), with w_i = v_i + g dt/2 (u at the end of a tick)
     * and sum |w_i + lambda n_i|^2 = sum 2 (S_i + g . p_i).
     */
    void restore() {
        Map<Ball, List<Ball>> groups = new LinkedHashMap<>();
        for (Ball ball : elasticNormals.keySet()) {
            groups.put(ball, new ArrayList<>(List.of(ball)));
        }
        for (List<Ball> pair : pairs) {
            List<Ball> first = groups.get(pair.get(0));
            List<Ball> second = groups.get(pair.get(1));
            if (first != second) {
                first.addAll(second);
                second.forEach(ball -> groups.put(ball, first));
            }
        }
        new LinkedHashSet<>(groups.values()).forEach(this::restore);
    }

    private void restore(List<Ball> group) {
        Vect h = gravity.times(dt / 2);
        double squares = 0;
        double along = 0;
        double target = 0;
        for (Ball ball : group) {
            if (lost.contains(ball) || ball.isCaptured() || !atStart.containsKey(ball)) {
                return;
            }
            Vect w = ball.velocity().plus(h);
            squares += w.dot(w);
            along += w.dot(elasticNormals.get(ball));
            target += 2 * (atStart.get(ball) + gravity.dot(ball.position()));
        }
        int n = group.size();
        double discriminant = along * along - n * (squares - target);
        if (discriminant < 0) {
            return;
        }
        double root = Math.sqrt(discriminant);
        double lambda = Math.abs(-along + root) <= Math.abs(-along - root) ? (-along + root) / n : (-along - root) / n;
        for (Ball ball : group) {
            double normalSpeed = ball.velocity().dot(elasticNormals.get(ball));
            if (normalSpeed + lambda < 0 || Math.abs(lambda) > normalSpeed / 2) {
                return;   // not a rounding of the bounce timing: leave the group alone
            }
        }
        for (Ball ball : group) {
            ball.setVelocity(ball.velocity().plus(elasticNormals.get(ball).times(lambda)));
        }
    }
}
