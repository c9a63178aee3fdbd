package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import java.util.ArrayList;
import java.util.List;

/**
 * What the editor's tests share: a board, an editor of it, and every message the editor said, in order. JUnit makes
 * a new test object for each test, so each starts from an empty board and a fresh editor; a test class builds its
 * board in its own {@code @BeforeEach}.
 */
abstract class EditorFixture {
    protected final Board board = new Board();
    protected final Editor editor = Editor.of(board);
    protected final List<String> messages = new ArrayList<>();

    EditorFixture() {
        editor.setMessageSink(messages::add);
    }

    protected Gizmo gizmo(String name) {
        return board.gizmo(name).orElseThrow(() -> new AssertionError("no gizmo " + name + " on " + board.gizmos()));
    }

    protected String lastMessage() {
        return messages.get(messages.size() - 1);
    }
}
