package gizmoball.editor;

import gizmoball.model.Board;
import java.util.List;
import java.util.Optional;

/**
 * Copy, cut, paste and duplicate in build mode: the selection as board-file text for the clipboard, and text
 * placed back under fresh names (each change one undo step of its editor, the pasted things selected). The board
 * operations themselves are {@link Transfer}'s.
 */
public final class ClipboardEdits {
    private final Editor editor;

    ClipboardEdits(Editor editor) {
        this.editor = editor;
    }

    /**
     * The board-file text of the selection (its lines, the connections among them, their key bindings), for the
     * clipboard; empty if nothing is selected.
     */
    public Optional<String> copySelected() {
        List<String> names = editor.selection();
        if (names.isEmpty()) {
            editor.say("Select a gizmo or ball to copy it");
            return Optional.empty();
        }
        editor.say("Copied " + Editor.listed(names));
        return Optional.of(Transfer.copy(editor.board(), names));
    }

    /** Copies the selection and deletes it (one undo step); the text for the clipboard, empty if nothing. */
    public Optional<String> cutSelected() {
        Optional<String> text = copySelected();
        if (text.isPresent() && !editor.selectionEdits().deleteAll("Cut ", editor.selection())) {
            return Optional.empty();
        }
        return text;
    }

    /**
     * Pastes copied board-file text: its gizmos and balls under fresh names, with the connections and key bindings
     * among them, where they were if that is free, else at the nearest place where all fit (one undo step). The
     * first of them is selected.
     */
    public boolean paste(String text) {
        return pasteOn(text, false, "Pasted ");
    }

    /** A copy of the selection beside it, under fresh names (one undo step), selected. */
    public boolean duplicateSelected() {
        List<String> names = editor.selection();
        if (names.isEmpty()) {
            return editor.refuse("Select a gizmo or ball to duplicate it");
        }
        return pasteOn(Transfer.copy(editor.board(), names), true, "Duplicated " + Editor.listed(names) + " as ");
    }

    private boolean pasteOn(String text, boolean elsewhere, String what) {
        Optional<Board> part = Transfer.read(text);
        if (part.isEmpty()) {
            return editor.refuse("Nothing to paste: the clipboard holds no board lines (such as Square S1 3 4)");
        }
        Optional<int[]> offset = Transfer.room(editor.board(), part.get(), elsewhere);
        if (offset.isEmpty()) {
            return editor.refuse("No room on the board for what is pasted");
        }
        int dx = offset.get()[0];
        int dy = offset.get()[1];
        List<String> names = Transfer.place(editor.board().copy(), part.get(), dx, dy);
        boolean done = editor.edit(what + Editor.listed(names), b -> Transfer.place(b, part.get(), dx, dy));
        if (done) {
            editor.selectAll(names, false);
        }
        return done;
    }
}
