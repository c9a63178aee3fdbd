package gizmoball.model.loop;

import gizmoball.model.gizmo.BallTaking;
import gizmoball.model.gizmo.GizmoBase;

import java.util.ArrayList;
import java.util.List;

/**
 * A uniform grid over the 20x20 cells: each cell knows the gizmo whose footprint covers it (gizmos never overlap,
 * so there is at most one). It answers "which cell is taken by whom" for editing, and "which gizmos can a ball
 * reach" for collision detection: the gizmos covering the cells of the box a ball sweeps in the time considered.
 * Every gizmo's shape lies inside its footprint (a swinging flipper's too), so no reachable shape is missed.
 * The board keeps one up to date as it edits; its members are for the board and its loop, not for views.
 */
public final class SpatialIndex {
    private final GizmoBase[][] cells = new GizmoBase[Arena.SIZE][Arena.SIZE];
    /** How many cells of each column are covered: a search skips the empty columns of its box. */
    private final int[] coveredInColumn = new int[Arena.SIZE];
    /** How many cells are covered in all. */
    private int covered;
    /** How many of its gizmos take balls out of play ({@link BallTaking#REMOVES}): a board without any asks none. */
    private int removers;

    /** The gizmo covering cell (cx, cy), or null (also outside the board). For the board, not for views. */
    public GizmoBase at(int cx, int cy) {
        return inside(cx, cy) ? cells[cx][cy] : null;
    }

    /** Whether (cx, cy) is a cell of the board. For the board, not for views. */
    public static boolean inside(int cx, int cy) {
        return cx >= 0 && cy >= 0 && cx < Arena.SIZE && cy < Arena.SIZE;
    }

    /** The gizmo covers its footprint's cells. For the board, not for views. */
    public void put(GizmoBase gizmo) {
        fill(gizmo, gizmo);
        removers += gizmo.ballTaking() == BallTaking.REMOVES ? 1 : 0;
    }

    /** The gizmo's footprint's cells are free. For the board, not for views. */
    public void remove(GizmoBase gizmo) {
        fill(gizmo, null);
        removers -= gizmo.ballTaking() == BallTaking.REMOVES ? 1 : 0;
    }

    /** Whether a gizmo in it takes balls out of play (a sink). For the loop. */
    boolean holdsRemovers() {
        return removers > 0;
    }

    private void fill(GizmoBase gizmo, GizmoBase value) {
        for (int cx = gizmo.x(); cx < gizmo.x() + gizmo.width(); cx++) {
            for (int cy = gizmo.y(); cy < gizmo.y() + gizmo.height(); cy++) {
                int change = (value != null ? 1 : 0) - (cells[cx][cy] != null ? 1 : 0);
                coveredInColumn[cx] += change;
                covered += change;
                cells[cx][cy] = value;
            }
        }
    }

    /**
     * The distinct gizmos covering any cell that meets the box [minX, maxX] x [minY, maxY] (board coordinates), in
     * column order. For the board and its loop, not for views.
     */
    public List<GizmoBase> within(double minX, double minY, double maxX, double maxY) {
        List<GizmoBase> found = new ArrayList<>(4);
        within(minX, minY, maxX, maxY, found);
        return found;
    }

    /** As {@link #within(double, double, double, double)}, into {@code found}, emptied first: the loop's, kept. */
    void within(double minX, double minY, double maxX, double maxY, List<GizmoBase> found) {
        found.clear();
        if (covered == 0) {
            return;
        }
        int x0 = Arena.cellOf(minX);
        int x1 = Arena.cellOf(maxX);
        int y0 = Arena.cellOf(minY);
        int y1 = Arena.cellOf(maxY);
        for (int cx = x0; cx <= x1; cx++) {
            if (coveredInColumn[cx] == 0) {
                continue;
            }
            for (int cy = y0; cy <= y1; cy++) {
                GizmoBase gizmo = cells[cx][cy];
                if (gizmo != null && !found.contains(gizmo)) {
                    found.add(gizmo);
                }
            }
        }
    }

}
