package gizmoball.bench;

import gizmoball.model.Board;
import gizmoball.model.gizmo.GizmoKind;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

/**
 * Reproducible boards of N bumpers and M balls for the dense scene, the scaling runs and the soak.
 * Bumpers (squares, circles, triangles in all rotations) fill random cells of rows 1-19; row 0 is kept
 * free so that even 380 bumpers leave room for balls. Balls start at the centres of random free cells,
 * top row first, with random velocities up to 10 L/s in each axis. Only bumpers: nothing on these
 * boards adds energy, so any energy gained is the loop's.
 */
final class RandomBoards {

    /** Cells available to bumpers: the board minus its top row. */
    static final int MAX_GIZMOS = Board.SIZE * (Board.SIZE - 1);

    private static final GizmoKind[] KINDS = {GizmoKind.SQUARE, GizmoKind.CIRCLE, GizmoKind.TRIANGLE};

    private RandomBoards() {
    }

    static Board generate(long seed, int gizmos, int balls) {
        if (gizmos > MAX_GIZMOS || balls > Board.SIZE * Board.SIZE - gizmos) {
            throw new IllegalArgumentException(gizmos + " gizmos and " + balls + " balls do not fit on the board");
        }
        Random random = new Random(seed);
        List<Integer> lowerCells = new ArrayList<>();
        for (int cell = Board.SIZE; cell < Board.SIZE * Board.SIZE; cell++) {
            lowerCells.add(cell);
        }
        Collections.shuffle(lowerCells, random);
        Board board = new Board();
        boolean[] taken = new boolean[Board.SIZE * Board.SIZE];
        for (int i = 0; i < gizmos; i++) {
            int cell = lowerCells.get(i);
            taken[cell] = true;
            String name = "G" + i;
            GizmoKind kind = KINDS[random.nextInt(KINDS.length)];
            board.addGizmo(kind, name, cell % Board.SIZE, cell / Board.SIZE);
            int turns = kind == GizmoKind.TRIANGLE ? random.nextInt(4) : 0;
            for (int t = 0; t < turns; t++) {
                board.rotate(name);
            }
        }
        List<Integer> free = new ArrayList<>();
        for (int cell = 0; cell < Board.SIZE * Board.SIZE; cell++) {
            if (!taken[cell]) {
                free.add(cell);
            }
        }
        List<Integer> top = new ArrayList<>(free.subList(0, Board.SIZE));
        List<Integer> rest = new ArrayList<>(free.subList(Board.SIZE, free.size()));
        Collections.shuffle(top, random);
        Collections.shuffle(rest, random);
        top.addAll(rest);
        for (int j = 0; j < balls; j++) {
            int cell = top.get(j);
            board.addBall("B" + j, cell % Board.SIZE + 0.5, cell / Board.SIZE + 0.5,
                    random.nextDouble() * 20 - 10, random.nextDouble() * 20 - 10);
        }
        return board;
    }
}
