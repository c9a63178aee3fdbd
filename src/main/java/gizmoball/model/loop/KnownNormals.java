package gizmoball.model.loop;

import physics.Vect;

/**
 * The normals of a ball's contacts it was last given, each with where the ball's centre and the surface point were:
 * most awake balls of a pile lie still from tick to tick, and such a ball is given the same normal again (the same
 * doubles, as a normal is reckoned from those four numbers alone) instead of a new vector every tick. Kept on the
 * ball, as {@link Ball.EnergyMarks} are; a copy of the ball starts with none.
 */
final class KnownNormals {
    /** More than a ball lying still has contacts but in a corner of a pile. */
    private static final int KEPT = 4;
    private final double[] ballX = new double[KEPT];
    private final double[] ballY = new double[KEPT];
    private final double[] fromX = new double[KEPT];
    private final double[] fromY = new double[KEPT];
    private final Vect[] normals = new Vect[KEPT];
    /** Where the next normal is kept, over the oldest. */
    private int next;

    /** The normal given for a centre at (x, y) and a surface point at (px, py), or null if none is known. */
    Vect find(double x, double y, double px, double py) {
        for (int i = 0; i < KEPT; i++) {
            if (normals[i] != null && ballX[i] == x && ballY[i] == y && fromX[i] == px && fromY[i] == py) {
                return normals[i];
            }
        }
        return null;
    }

    /**
     * A kept normal whose components are (nx, ny) exactly, or null: a ball sliding along a flat surface moves every
     * tick, but its normal there is most often the same to the last bit, and the same vector serves.
     */
    Vect same(double nx, double ny) {
        for (int i = 0; i < KEPT; i++) {
            if (normals[i] != null && normals[i].x() == nx && normals[i].y() == ny) {
                return normals[i];
            }
        }
        return null;
    }

    /** Keeps the normal given for a centre at (x, y) and a surface point at (px, py). */
    void keep(double x, double y, double px, double py, Vect normal) {
        ballX[next] = x;
        ballY[next] = y;
        fromX[next] = px;
        fromY[next] = py;
        normals[next] = normal;
        next = (next + 1) % KEPT;
    }
}
