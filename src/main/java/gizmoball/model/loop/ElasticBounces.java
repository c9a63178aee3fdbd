package gizmoball.model.loop;

import java.util.Arrays;
import java.util.List;

/**
 * The elastic bounces of a cluster solve that kept the energy, for the shadow energy: each ball's bounce is along the
 * normal of the contact that pressed it most, and balls that pressed each other keep their energy together. Its books
 * (per ball: the strongest contact's impulse and normal's components, and whether that normal points away from the
 * ball, it being the row's other ball) are kept and grown to the largest cluster seen.
 */
final class ElasticBounces {
    private final ShadowEnergy energy;
    private double[] most = new double[0];
    private double[] strongestX = new double[0];
    private double[] strongestY = new double[0];
    private boolean[] against = new boolean[0];

    ElasticBounces(ShadowEnergy energy) {
        this.energy = energy;
    }

    /** The cluster's bounces, {@code compression} the impulse the solve gave each of its rows. */
    void note(ContactCluster cluster, double[] compression) {
        List<ClusterRow> rows = cluster.rows();
        List<Ball> balls = cluster.balls();
        if (most.length < balls.size()) {
            most = new double[balls.size()];
            strongestX = new double[balls.size()];
            strongestY = new double[balls.size()];
            against = new boolean[balls.size()];
        }
        Arrays.fill(most, 0, balls.size(), 0);   // a ball with none above 0 had no contact pressed
        for (int i = 0; i < rows.size(); i++) {
            ClusterRow row = rows.get(i);
            double change = compression[i];
            if (change <= 0) {
                continue;
            }
            if (change > most[row.ball()]) {
                strongest(row.ball(), change, row, false);
            }
            if (row.other() instanceof ClusterRow.Other.InCluster in) {
                if (change > most[in.index()]) {
                    strongest(in.index(), change, row, true);
                }
                energy.met(balls.get(row.ball()), balls.get(in.index()));
            }
        }
        for (int k = 0; k < balls.size(); k++) {
            if (most[k] > 0) {
                if (against[k]) {   // normal.neg()
                    energy.bounced(balls.get(k), -strongestX[k] + 0.0, -strongestY[k] + 0.0);
                } else {
                    energy.bounced(balls.get(k), strongestX[k], strongestY[k]);
                }
            }
        }
    }

    /** The row pressed ball {@code k} with {@code change}, more than any before; its normal points away if against. */
    private void strongest(int k, double change, ClusterRow row, boolean against) {
        most[k] = change;
        strongestX[k] = row.normalX();
        strongestY[k] = row.normalY();
        this.against[k] = against;
    }
}
