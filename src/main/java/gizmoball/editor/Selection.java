package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * What is selected in build mode, in the order it was selected: gizmos and balls, or the outer walls alone. Names
 * of things the board no longer has are kept (an undo may bring them back) but never reported.
 */
final class Selection {
    private final Board board;
    private final List<String> names = new ArrayList<>();

    Selection(Board board) {
        this.board = board;
    }

    /** The last selected that (still) exists: the one whose connections and properties are shown. */
    Optional<String> last() {
        for (int i = names.size() - 1; i >= 0; i--) {
            if (exists(names.get(i))) {
                return Optional.of(names.get(i));
            }
        }
        return Optional.empty();
    }

    /** Every selected gizmo and ball that (still) exists, in the order selected; the outer walls are not among them. */
    List<String> things() {
        return names.stream().filter(n -> !isWalls(n) && exists(n)).toList();
    }

    /** Only {@code name}, or nothing for null. */
    void only(String name) {
        names.clear();
        if (name != null) {
            names.add(name);
        }
    }

    /** Puts the gizmo or ball in, or takes it out if it is in; whether it went in. */
    boolean toggle(String name) {
        names.removeIf(Selection::isWalls);
        boolean added = !names.remove(name);
        if (added) {
            names.add(name);
        }
        return added;
    }

    /** Adds these gizmos and balls after what is selected, or instead of it unless {@code adding}. */
    void addAll(List<String> more, boolean adding) {
        if (!adding) {
            names.clear();
        }
        names.removeIf(Selection::isWalls);
        more.stream().filter(n -> !names.contains(n)).forEach(names::add);
    }

    /** Makes {@code name} the last selected. */
    void bringToFront(String name) {
        names.remove(name);
        names.add(name);
    }

    void remove(String name) {
        names.remove(name);
    }

    void clear() {
        names.clear();
    }

    int size() {
        return names.size();
    }

    private boolean exists(String name) {
        return isWalls(name) || board.gizmo(name).isPresent() || board.ball(name).isPresent();
    }

    static boolean isWalls(String name) {
        return TriggerSource.named(name) instanceof TriggerSource.OuterWalls;
    }
}
