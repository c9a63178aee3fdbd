package gizmoball.boardfile;

import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.game.GameRules;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * Everything a board file records about a board, as a value, so two boards can be compared with equals (Board
 * itself has no equality): the editor's history uses it to tell whether a change made elsewhere (Open, back
 * from play) altered the design, and the tests to compare boards read, written and edited.
 */
public record BoardContents(List<GizmoState> gizmos, List<BallState> balls, List<Connection> connections,
                     List<KeyBinding> keyBindings, double gravity, double mu, double mu2, GameRules game) {

    /** @param setting what the gizmo's properties set beyond its place, size, turn and colour (exactly compared) */
    public record GizmoState(String name, GizmoKind kind, int x, int y, int width, int height, int rotation,
                      Optional<Rgb> colour, Setting setting) {
    }

    /** Doubles compared exactly (records use Double.compare semantics), so a lost bit shows. */
    public record BallState(String name, double x, double y, double vx, double vy, boolean captured) {
    }

    /**
     * The same contents with the connections and key bindings in one fixed order: they are sets, whose order a
     * board file does not say (a connection taken away and made again is the same board, though listed last).
     */
    public BoardContents withSetsSorted() {
        return new BoardContents(gizmos, balls,
                connections.stream().sorted(Comparator.comparing(Connection::toString)).toList(),
                keyBindings.stream().sorted(Comparator.comparing(KeyBinding::toString)).toList(), gravity, mu, mu2, game);
    }

    /** The same design: equal contents, the connections and key bindings in any order. */
    public static boolean sameDesign(Board a, Board b) {
        return of(a).withSetsSorted().equals(of(b).withSetsSorted());
    }

    /** What differs from {@code other}, element by element, so a failure names the one ball or gizmo at fault. */
    public List<String> differences(BoardContents other) {
        List<String> differences = new ArrayList<>();
        compare("gizmo", gizmos, other.gizmos, differences);
        compare("ball", balls, other.balls, differences);
        compare("connection", connections, other.connections, differences);
        compare("key binding", keyBindings, other.keyBindings, differences);
        compare("constants", List.of(gravity, mu, mu2), List.of(other.gravity, other.mu, other.mu2), differences);
        compare("game rules", List.of(game), List.of(other.game), differences);
        return differences;
    }

    private static <T> void compare(String what, List<T> mine, List<T> theirs, List<String> differences) {
        for (int i = 0; i < Math.max(mine.size(), theirs.size()); i++) {
            T a = i < mine.size() ? mine.get(i) : null;
            T b = i < theirs.size() ? theirs.get(i) : null;
            if (!Objects.equals(a, b)) {
                differences.add(what + " " + i + ": " + a + " became " + b);
            }
        }
    }

    public static BoardContents of(Board board) {
        return new BoardContents(
                board.gizmos().stream().map(BoardContents::state).toList(),
                board.balls().stream().map(BoardContents::state).toList(),
                List.copyOf(board.connections()), List.copyOf(board.keyBindings()),
                board.gravity(), board.mu(), board.mu2(), board.gameRules());
    }

    private static GizmoState state(Gizmo g) {
        return new GizmoState(g.name(), g.kind(), g.x(), g.y(), g.width(), g.height(), g.rotation(), g.colour(),
                g.setting());
    }

    private static BallState state(BallView b) {
        return new BallState(b.name(), b.position().x(), b.position().y(), b.velocity().x(), b.velocity().y(),
                b.isCaptured());
    }
}
