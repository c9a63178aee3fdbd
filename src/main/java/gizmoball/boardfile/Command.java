package gizmoball.boardfile;

import static gizmoball.boardfile.Decimals.format;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.GizmoKind;
import gizmoball.model.KeyEdge;
import java.util.Locale;

/**
 * One parsed board-file command: {@link #applyTo} performs it on a board through the board's own editing
 * operations (so every rule of the model applies), {@link #toLine()} writes it back in canonical form.
 */
public sealed interface Command {

    /** Performs the command, or throws the board's refusal leaving the board as it was. */
    void applyTo(Board board);

    String toLine();

    /** Square, Circle, Triangle, LeftFlipper or RightFlipper with the top-left cell of its footprint. */
    record AddGizmo(GizmoKind kind, String name, int x, int y) implements Command {
        public void applyTo(Board board) {
            board.addGizmo(kind, name, x, y);
        }

        public String toLine() {
            return CommandWord.of(kind).spelling() + " " + name + " " + x + " " + y;
        }
    }

    /** (x2, y2) is the exclusive bottom-right corner. */
    record AddAbsorber(String name, int x1, int y1, int x2, int y2) implements Command {
        public void applyTo(Board board) {
            board.addAbsorber(name, x1, y1, x2, y2);
        }

        public String toLine() {
            return CommandWord.ABSORBER.spelling() + " " + name + " " + x1 + " " + y1 + " " + x2 + " " + y2;
        }
    }

    record AddBall(String name, double x, double y, double vx, double vy) implements Command {
        public void applyTo(Board board) {
            board.addBall(name, x, y, vx, vy);
        }

        public String toLine() {
            return CommandWord.BALL.spelling() + " " + name + " " + format(x) + " " + format(y)
                    + " " + format(vx) + " " + format(vy);
        }
    }

    record Rotate(String name) implements Command {
        public void applyTo(Board board) {
            board.rotate(name);
        }

        public String toLine() {
            return CommandWord.ROTATE.spelling() + " " + name;
        }
    }

    record Delete(String name) implements Command {
        public void applyTo(Board board) {
            board.delete(name);
        }

        public String toLine() {
            return CommandWord.DELETE.spelling() + " " + name;
        }
    }

    /** A gizmo to a whole cell or a ball centre anywhere: which one is known only once the name is resolved. */
    record Move(String name, double x, double y) implements Command {
        public void applyTo(Board board) {
            if (board.gizmo(name).isPresent()) {
                if (x != Math.rint(x) || y != Math.rint(y)) {
                    throw new BoardEditException("gizmo " + name + " can only move to a whole cell, not ("
                            + format(x) + ", " + format(y) + ")");
                }
                // A cast saturates, so a far-off cell stays far off and the board calls it outside.
                board.moveGizmo(name, (int) x, (int) y);
            } else if (board.ball(name).isPresent()) {
                board.moveBall(name, x, y);
            } else {
                throw new BoardEditException("cannot move " + name + ": no gizmo or ball named " + name);
            }
        }

        public String toLine() {
            return CommandWord.MOVE.spelling() + " " + name + " " + format(x) + " " + format(y);
        }
    }

    record Connect(String source, String target) implements Command {
        public void applyTo(Board board) {
            board.connect(source, target);
        }

        public String toLine() {
            return CommandWord.CONNECT.spelling() + " " + source + " " + target;
        }
    }

    record KeyConnect(int keyCode, KeyEdge edge, String gizmo) implements Command {
        public void applyTo(Board board) {
            board.bindKey(keyCode, edge, gizmo);
        }

        public String toLine() {
            return CommandWord.KEY_CONNECT.spelling() + " key " + keyCode + " " + edge.name().toLowerCase(Locale.ROOT)
                    + " " + gizmo;
        }
    }

    record Gravity(double g) implements Command {
        public void applyTo(Board board) {
            board.setGravity(g);
        }

        public String toLine() {
            return CommandWord.GRAVITY.spelling() + " " + format(g);
        }
    }

    record Friction(double mu, double mu2) implements Command {
        public void applyTo(Board board) {
            board.setFriction(mu, mu2);
        }

        public String toLine() {
            return CommandWord.FRICTION.spelling() + " " + format(mu) + " " + format(mu2);
        }
    }
}
