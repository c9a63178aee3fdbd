package gizmoball.boardfile;

/**
 * A fact of a board that board-file lines state: a gizmo or ball itself (its kind and place), one gizmo's
 * rotation, colour or flipper state, gravity, friction, or one element of a set (a connection, a key binding),
 * which is its line. A canonical file states each subject in one group of lines; a save compares a subject's
 * lines before and after an edit to know whether the author's lines for it can stay as they are.
 *
 * @param aspect what is stated: "thing", "line", or the record of the command that states one fact ("Rotate",
 *               "Colour", "Gravity", ...)
 * @param name   the gizmo or ball it is stated of, empty for the board's constants, the line for a set element
 */
public record Subject(String aspect, String name) {

    static Subject thing(String name) {
        return new Subject("thing", name);
    }

    static Subject line(String line) {
        return new Subject("line", line);
    }

    /** A gizmo or ball itself: what a Move or Delete line of it acts on. */
    boolean isThing() {
        return aspect.equals("thing");
    }
}
