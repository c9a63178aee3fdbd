package gizmoball.editor;

import gizmoball.boardfile.BoardFiles;
import gizmoball.boardfile.LoadResult;
import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.KeyBinding;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * Renaming, copying and pasting gizmos and balls, as board operations. What is copied is board-file text (the
 * lines of the things, the connections among them and their key bindings), so it goes between windows and into a
 * text editor alike, and anything that loads as a board pastes. Pasted things get fresh names and keep their
 * connections to each other; they go where they were if that is free, else at the nearest offset where all fit.
 */
final class Transfer {
    /** How far (in cells) a paste looks for room around where the things were. */
    private static final int SEARCH = Board.SIZE;

    private Transfer() {
    }

    /** The board-file text of the named gizmos and balls of {@code board}, with what links them. */
    static String copy(Board board, List<String> names) {
        Board part = new Board();
        Map<String, String> same = new HashMap<>();
        names.forEach(n -> same.put(n, n));
        for (String name : names) {
            board.gizmo(name).ifPresent(g -> addGizmo(part, board, g, name, 0, 0));
            board.ball(name).ifPresent(b -> part.addBall(name, b.position().x(), b.position().y(), b.velocity().x(),
                    b.velocity().y()));
        }
        link(part, board, same);
        return BoardFiles.toText(part);
    }

    /** The things of a copied text, or why there are none. */
    static Optional<Board> read(String text) {
        LoadResult loaded = BoardFiles.loadSkippingBadLines("clipboard", text);
        Board part = loaded.board();
        if (!loaded.skippedLines().isEmpty() || part.gizmos().isEmpty() && part.balls().isEmpty()) {
            return Optional.empty();
        }
        return Optional.of(part);
    }

    /**
     * Places every gizmo and ball of {@code part} on {@code target} moved by (dx, dy) under fresh names, with the
     * connections and key bindings among them; the new names in order. Throws the board's refusal.
     */
    static List<String> place(Board target, Board part, int dx, int dy) {
        NameGenerator names = new NameGenerator(target);
        Map<String, String> renamed = new HashMap<>();
        List<String> placed = new ArrayList<>();
        for (Gizmo g : part.gizmos()) {
            String name = names.nextGizmoName(g.kind());
            addGizmo(target, part, g, name, dx, dy);
            renamed.put(g.name(), name);
            placed.add(name);
        }
        for (BallView b : part.balls()) {
            String name = names.nextBallName();
            target.addBall(name, b.position().x() + dx, b.position().y() + dy, b.velocity().x(), b.velocity().y());
            placed.add(name);
        }
        link(target, part, renamed);
        return placed;
    }

    /**
     * The offset at which all of {@code part} fits on {@code board}: none if it fits where it was (unless
     * {@code elsewhere}: a duplicate), else the nearest, ring by ring, right and down first.
     */
    static Optional<int[]> room(Board board, Board part, boolean elsewhere) {
        for (int d = elsewhere ? 1 : 0; d <= SEARCH; d++) {
            for (int dy = -d; dy <= d; dy++) {
                for (int dx = -d; dx <= d; dx++) {
                    if (Math.max(Math.abs(dx), Math.abs(dy)) == d && fits(board, part, dx, dy)) {
                        return Optional.of(new int[] {dx, dy});
                    }
                }
            }
        }
        return Optional.empty();
    }

    private static boolean fits(Board board, Board part, int dx, int dy) {
        try {
            place(board.copy(), part, dx, dy);
            return true;
        } catch (BoardEditException refused) {
            return false;
        }
    }

    /**
     * Gives the gizmo or ball {@code name} the name {@code newName}, with everything that names it following:
     * connections, key bindings, its portal's pair, colour, rotation, points and drain.
     */
    static void rename(Board board, String name, String newName) {
        if (newName.isEmpty() || newName.chars().anyMatch(Character::isWhitespace)) {
            throw new BoardEditException("a name is one word without spaces, not '" + newName + "'");
        }
        Optional<BallView> ball = board.ball(name);
        if (ball.isPresent()) {
            BallView b = ball.get();
            board.delete(name);
            board.addBall(newName, b.position().x(), b.position().y(), b.velocity().x(), b.velocity().y());
            return;
        }
        Gizmo g = board.gizmo(name).orElseThrow(() -> new BoardEditException("no gizmo or ball named " + name));
        Board before = board.copy();
        board.delete(name);
        addGizmo(board, before, g, newName, 0, 0);
        Map<String, String> renamed = new HashMap<>();
        before.gizmos().forEach(other -> renamed.put(other.name(), other.name()));
        renamed.put(name, newName);
        relink(board, before, name, renamed);
    }

    /** A gizmo like {@code g} of {@code from}, named {@code name}, moved by (dx, dy): kind, turns, colour, setting, rules. */
    private static void addGizmo(Board to, Board from, Gizmo g, String name, int dx, int dy) {
        if (g.kind().sizedByCorners()) {
            to.addAbsorber(name, g.x() + dx, g.y() + dy, g.x() + dx + g.width(), g.y() + dy + g.height());
        } else {
            to.addGizmo(g.kind(), name, g.x() + dx, g.y() + dy);
        }
        for (int turn = 0; turn < g.rotation(); turn++) {
            to.rotate(name);
        }
        to.setColour(name, g.colour());
        if (!g.setting().isDefault() && g.setting().names().isEmpty()) {
            to.set(name, g.setting());
        }
        if (from.gameRules().ownPoints().containsKey(g.name())) {
            to.setPoints(name, from.gameRules().pointsOf(g.name(), g.kind()));
        }
        if (from.gameRules().isDrain(g.name())) {
            to.setDrain(name, true);
        }
    }

    /**
     * The connections, key bindings and settings naming others (portals' pairs) of {@code from} among the names
     * {@code renamed} knows, renamed.
     */
    private static void link(Board to, Board from, Map<String, String> renamed) {
        for (Gizmo g : from.gizmos()) {
            List<String> named = g.setting().names();
            if (!named.isEmpty() && renamed.containsKey(g.name()) && renamed.keySet().containsAll(named)) {
                to.set(renamed.get(g.name()), g.setting().renamed(renamed::get));
            }
        }
        for (Connection c : from.connections()) {
            if (c.source() instanceof TriggerSource.OfGizmo s && renamed.containsKey(s.gizmo())
                    && renamed.containsKey(c.target())) {
                to.connect(TriggerSource.gizmo(renamed.get(s.gizmo())), renamed.get(c.target()), c.order());
            }
        }
        for (KeyBinding k : from.keyBindings()) {
            if (renamed.containsKey(k.gizmo())) {
                to.bindKey(k.keyCode(), k.edge(), renamed.get(k.gizmo()), k.order());
            }
        }
    }

    /** After a rename: every connection, binding and pair that named the gizmo, walls' connections included. */
    private static void relink(Board to, Board from, String name, Map<String, String> renamed) {
        from.gizmo(name).map(Gizmo::setting).filter(setting -> !setting.names().isEmpty())
                .ifPresent(setting -> to.set(renamed.get(name), setting.renamed(renamed::get)));
        for (Connection c : from.connections()) {
            boolean fromIt = c.source() instanceof TriggerSource.OfGizmo s && s.gizmo().equals(name);
            if (fromIt || c.target().equals(name)) {
                TriggerSource source = fromIt ? TriggerSource.gizmo(renamed.get(name)) : c.source();
                to.connect(source, renamed.get(c.target()), c.order());
            }
        }
        for (KeyBinding k : from.keyBindings()) {
            if (k.gizmo().equals(name)) {
                to.bindKey(k.keyCode(), k.edge(), renamed.get(name), k.order());
            }
        }
    }
}
