package gizmoball.fuzz;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.gizmo.Flipper;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;

import java.util.List;
import java.util.SplittableRandom;
import java.util.function.UnaryOperator;

/**
 * Puts balls on a generated board: anywhere free, touching a gizmo (a flipper's bar or its pivot end among them),
 * touching a ball already placed, against an outer wall or in a corner, or in a cell left free between gizmos; each at rest, slow, or at up to 100 L/s.
 * A spot the board refuses (on a gizmo or a ball) is tried again elsewhere.
 */
final class BallPlacer {
    static final double MAX_SPEED = 100;
    private static final double R = Board.BALL_RADIUS;
    private static final int ATTEMPTS = 40;
    /** Tries at free spots for a ball that found no place in its {@link #ATTEMPTS}: every board gets its 5 balls. */
    private static final int LAST_TRIES = 2_000;

    private final SplittableRandom random;
    private final Board board;
    private final UnaryOperator<String> names;

    BallPlacer(SplittableRandom random, Board board, UnaryOperator<String> names) {
        this.random = random;
        this.board = board;
        this.names = names;
    }

    /** Tries to place {@code count} balls; returns how many the board took. */
    int place(int count) {
        int placed = 0;
        for (int i = 0; i < count; i++) {
            String name = names.apply("B");
            boolean done = false;
            for (int attempt = 0; attempt < ATTEMPTS && !done; attempt++) {
                done = tryAt(name, spot());
            }
            for (int attempt = 0; attempt < LAST_TRIES && !done; attempt++) {
                done = tryAt(name, anywhere());
            }
            placed += done ? 1 : 0;
        }
        return placed;
    }

    /** Places one ball at {@code at}, at rest, slow or fast; false where the board refuses it there. */
    boolean placeAt(Point at) {
        return tryAt(names.apply("B"), at);
    }

    private boolean tryAt(String name, Point at) {
        double[] v = velocity();
        try {
            board.addBall(name, at.x(), at.y(), v[0], v[1]);
            return true;
        } catch (BoardEditException refused) {
            return false;   // on a gizmo, a ball or off the board: another spot
        }
    }

    private Point anywhere() {
        return new Point(random.nextDouble(R, Board.SIZE - R), random.nextDouble(R, Board.SIZE - R));
    }

    private Point spot() {
        int how = random.nextInt(22);
        List<Gizmo> gizmos = board.gizmos();
        List<BallView> balls = board.balls().stream().filter(b -> !b.isCaptured()).toList();
        if (how < 6 || gizmos.isEmpty()) {
            return anywhere();
        }
        if (how < 11) {
            return touching(Bodies.of(gizmos.get(random.nextInt(gizmos.size()))));
        }
        if (how < 14) {
            List<Flipper> flippers = gizmos.stream().filter(Flipper.class::isInstance).map(Flipper.class::cast).toList();
            if (!flippers.isEmpty()) {
                return touchingFlipper(flippers.get(random.nextInt(flippers.size())));
            }
        }
        if (how < 18 && !balls.isEmpty()) {
            BallView other = balls.get(random.nextInt(balls.size()));
            // A third straight above it (under gravity, a stack balanced on a point), else anywhere round it.
            double angle = random.nextInt(3) == 0 ? -Math.PI / 2 : random.nextDouble(0, 2 * Math.PI);
            return around(new Point(other.position().x(), other.position().y()), 2 * R + gap(), angle);
        }
        if (how >= 20) {
            return againstWall();
        }
        // Somewhere in a cell: its centre, or against one of its sides.
        double[] inCell = {0.5, R, 1 - R};
        return new Point(random.nextInt(Board.SIZE) + inCell[random.nextInt(3)],
                random.nextInt(Board.SIZE) + inCell[random.nextInt(3)]);
    }

    /** Touching an outer wall, or in a corner of the board. */
    private Point againstWall() {
        double along = random.nextInt(4) == 0 ? R : random.nextDouble(R, Board.SIZE - R);
        double near = R + gap();
        double far = Board.SIZE - near;
        return switch (random.nextInt(4)) {
            case 0 -> new Point(near, along);
            case 1 -> new Point(far, along);
            case 2 -> new Point(along, near);
            default -> new Point(along, far);
        };
    }

    /** Mostly exactly touching (to rounding), else a hair away. */
    private double gap() {
        return random.nextInt(3) == 0 ? random.nextDouble(0, 1e-3) : 0;
    }

    private static Point around(Point centre, double distance, double angle) {
        return new Point(centre.x() + distance * Math.cos(angle), centre.y() + distance * Math.sin(angle));
    }

    /** At the flipper's pivot end (0.5 L from the pivot, as in the pivot-end reproduction), or along its bar. */
    private Point touchingFlipper(Flipper flipper) {
        Solid.Capsule bar = Bodies.flipper(flipper);
        double along = random.nextInt(3) == 0 ? 0 : random.nextDouble();
        Point from = new Point(bar.a().x() + along * (bar.b().x() - bar.a().x()),
                bar.a().y() + along * (bar.b().y() - bar.a().y()));
        return outward(bar, from);
    }

    /** Touching the body, found along a random ray from a point of it. */
    private Point touching(Solid body) {
        double[] box = body.bounds();
        Point from = body instanceof Solid.Capsule bar ? bar.a()
                : new Point((box[0] + box[2]) / 2, (box[1] + box[3]) / 2);
        return outward(body, from);
    }

    /**
     * The point at distance {@code R + gap} from the body along a random ray from {@code from} (a point of the body):
     * the body is convex, so its distance grows along the ray once outside, and bisection finds the crossing; the
     * outer end is kept, so the ball never starts inside.
     */
    private Point outward(Solid body, Point from) {
        double angle = random.nextDouble(0, 2 * Math.PI);
        double dx = Math.cos(angle);
        double dy = Math.sin(angle);
        double want = R + gap();
        double inner = 0;
        double outer = 2 * Board.SIZE;
        for (int i = 0; i < 80; i++) {
            double mid = (inner + outer) / 2;
            if (body.signedDistance(from.x() + mid * dx, from.y() + mid * dy) < want) {
                inner = mid;
            } else {
                outer = mid;
            }
        }
        return new Point(from.x() + outer * dx, from.y() + outer * dy);
    }

    private double[] velocity() {
        int how = random.nextInt(10);
        if (how < 3) {
            return new double[] {0, 0};
        }
        double speed = how == 3 ? random.nextDouble(0, 2) : random.nextDouble(0, MAX_SPEED);
        double angle = how == 4 ? random.nextInt(4) * Math.PI / 2 : random.nextDouble(0, 2 * Math.PI);
        return new double[] {speed * Math.cos(angle), speed * Math.sin(angle)};
    }
}
