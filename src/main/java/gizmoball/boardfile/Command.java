package gizmoball.boardfile;

import static gizmoball.boardfile.Decimals.format;

/** One parsed board-file command. {@link #toLine()} writes it back in canonical form. */
public sealed interface Command {

    String toLine();

    /** Square, Circle, Triangle, LeftFlipper or RightFlipper with the top-left cell of its footprint. */
    record AddGizmo(CommandWord word, String name, int x, int y) implements Command {
        public String toLine() {
            return word.spelling() + " " + name + " " + x + " " + y;
        }
    }

    /** (x2, y2) is the exclusive bottom-right corner. */
    record AddAbsorber(String name, int x1, int y1, int x2, int y2) implements Command {
        public String toLine() {
            return CommandWord.ABSORBER.spelling() + " " + name + " " + x1 + " " + y1 + " " + x2 + " " + y2;
        }
    }

    record AddBall(String name, double x, double y, double vx, double vy) implements Command {
        public String toLine() {
            return CommandWord.BALL.spelling() + " " + name + " " + format(x) + " " + format(y)
                    + " " + format(vx) + " " + format(vy);
        }
    }

    record Rotate(String name) implements Command {
        public String toLine() {
            return CommandWord.ROTATE.spelling() + " " + name;
        }
    }

    record Delete(String name) implements Command {
        public String toLine() {
            return CommandWord.DELETE.spelling() + " " + name;
        }
    }

    /** A gizmo to a whole cell or a ball centre anywhere: which one is known only once the name is resolved. */
    record Move(String name, double x, double y) implements Command {
        public String toLine() {
            return CommandWord.MOVE.spelling() + " " + name + " " + format(x) + " " + format(y);
        }
    }

    record Connect(String source, String target) implements Command {
        public String toLine() {
            return CommandWord.CONNECT.spelling() + " " + source + " " + target;
        }
    }

    record KeyConnect(int keyCode, boolean down, String gizmo) implements Command {
        public String toLine() {
            return CommandWord.KEY_CONNECT.spelling() + " key " + keyCode + " " + (down ? "down" : "up") + " " + gizmo;
        }
    }

    record Gravity(double g) implements Command {
        public String toLine() {
            return CommandWord.GRAVITY.spelling() + " " + format(g);
        }
    }

    record Friction(double mu, double mu2) implements Command {
        public String toLine() {
            return CommandWord.FRICTION.spelling() + " " + format(mu) + " " + format(mu2);
        }
    }
}
