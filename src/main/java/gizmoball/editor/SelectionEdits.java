package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;

/**
 * Delete, rotate and move what is selected in build mode (the menus, the keys, the tools' gestures): each change
 * one undo step of its editor, whether it acts on one gizmo or ball or on several.
 */
final class SelectionEdits {
    private final Editor editor;
    private final Selection selection;

    SelectionEdits(Editor editor, Selection selection) {
        this.editor = editor;
        this.selection = selection;
    }

    /** Deletes everything selected (one undo step). */
    boolean deleteSelected() {
        List<String> names = selection.things();
        if (names.isEmpty()) {
            editor.say("Nothing selected to delete");
            return false;
        }
        return names.size() == 1 ? delete(names.get(0)) : deleteAll("Deleted ", names);
    }

    /**
     * Turns the selected gizmo 90 degrees clockwise; of several selected, each that turns in its own cells (one undo
     * step; circles and absorbers look the same turned and stay).
     */
    boolean rotateSelected() {
        List<Gizmo> gizmos = selection.things().stream().flatMap(n -> board().gizmo(n).stream()).toList();
        if (gizmos.isEmpty()) {
            editor.say("Select a gizmo to rotate");
            return false;
        }
        if (gizmos.size() == 1) {
            return rotate(gizmos.get(0));
        }
        List<String> turning = gizmos.stream().filter(g -> g.kind().rotates()).map(Gizmo::name).toList();
        if (turning.isEmpty()) {
            return editor.refuse("Circles and absorbers look the same turned: none of the selection can be rotated");
        }
        return editor.edit("Rotated " + Editor.listed(turning), b -> turning.forEach(b::rotate));
    }

    /**
     * Moves the selected gizmo one cell, or the selected ball a quarter cell, in the direction (dx, dy); several
     * selected move together (one undo step), by a cell, or a quarter cell if they are all balls.
     */
    boolean nudgeSelected(int dx, int dy) {
        List<String> group = selection.things();
        if (group.size() > 1) {
            double step = group.stream().anyMatch(n -> board().gizmo(n).isPresent()) ? 1 : Picking.BALL_SNAP;
            return moveGroup(group, dx * step, dy * step);
        }
        Optional<Gizmo> gizmo = editor.selectedGizmo();
        Optional<BallView> ball = editor.selectedBall();
        if (gizmo.isPresent()) {
            Gizmo g = gizmo.get();
            int x = g.x() + dx;
            int y = g.y() + dy;
            return editor.edit("Moved " + g.name() + " to (" + x + "," + y + ")", b -> b.moveGizmo(g.name(), x, y));
        }
        if (ball.isPresent()) {
            BallView b0 = ball.get();
            double x = b0.position().x() + dx * Picking.BALL_SNAP;
            double y = b0.position().y() + dy * Picking.BALL_SNAP;
            return editor.edit("Moved " + b0.name() + " to (" + x + ", " + y + ")", b -> b.moveBall(b0.name(), x, y));
        }
        editor.say("Select a gizmo or ball to move it with the arrow keys");
        return false;
    }

    /**
     * Deletes the named gizmos and balls as one undo step: the balls first, since an absorber takes the balls it
     * holds with it.
     */
    boolean deleteAll(String verb, List<String> names) {
        List<String> ordered = new ArrayList<>(names);
        ordered.sort(Comparator.comparing((String n) -> board().ball(n).isEmpty()));
        boolean done = editor.edit(verb + Editor.listed(names), b -> ordered.forEach(b::delete));
        if (done) {
            selection.clear();
            editor.stateChanged();
        }
        return done;
    }

    /** Moves the named gizmos and balls together by (dx, dy) L (one undo step); no move is no edit. */
    boolean moveGroup(List<String> names, double dx, double dy) {
        if (dx == 0 && dy == 0) {
            return true;
        }
        return editor.edit("Moved " + Editor.listed(names) + " by (" + brief(dx) + "," + brief(dy) + ")",
                b -> b.moveGroup(names, dx, dy));
    }

    /**
     * Turns a gizmo 90 degrees clockwise. A kind that looks the same turned (a circle, an absorber:
     * {@link GizmoKind#rotates}) is refused with a message and leaves no undo step, rather than "rotating" with
     * nothing to see.
     */
    boolean rotate(Gizmo gizmo) {
        if (!gizmo.kind().rotates()) {
            editor.say(gizmo.name() + " is " + gizmo.kind().withArticle()
                    + ": it looks the same turned, so it cannot be rotated");
            editor.stateChanged();
            return false;
        }
        return editor.edit("Rotated " + gizmo.name(), b -> b.rotate(gizmo.name()));
    }

    boolean delete(String name) {
        selection.remove(name);
        return editor.edit("Deleted " + name, b -> b.delete(name));
    }

    /** A distance as a message shows it: 2, not 2.0; 0.25 as it is. */
    private static String brief(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }

    private Board board() {
        return editor.board();
    }
}
