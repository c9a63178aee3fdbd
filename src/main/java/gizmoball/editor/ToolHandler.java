package gizmoball.editor;

import gizmoball.model.gizmo.GizmoKind;
import java.util.Optional;

/**
 * What one tool does with the pointer and the keys. Handlers keep no state of their own: the half-done step
 * is the editor's {@link PendingStep}, so switching tools or cancelling needs nothing from them.
 */
interface ToolHandler {
    /** The handler of tool {@code t} in {@code editor}. */
    static ToolHandler of(Tool t, Editor editor) {
        return switch (t) {
            case BALL -> new PlaceBallTool(editor);
            case SELECT -> new SelectTool(editor);
            case ROTATE -> new RotateTool(editor);
            case DELETE -> new DeleteTool(editor);
            case CONNECT -> new ConnectTool(editor, true);
            case DISCONNECT -> new ConnectTool(editor, false);
            case KEY_CONNECT -> new KeyConnectTool(editor, true);
            case KEY_DISCONNECT -> new KeyConnectTool(editor, false);
            default -> placing(t.kind().orElseThrow(), editor);
        };
    }

    /** Every other tool places a gizmo of its kind: dragged out by its corners if it is sized so, else on one cell. */
    private static ToolHandler placing(GizmoKind kind, Editor editor) {
        return kind.sizedByCorners() ? new PlaceAbsorberTool(editor, kind) : new PlaceGizmoTool(editor, kind);
    }

    /** The preview under the pointer with no button down, or null for none. */
    default Preview hover(double x, double y) {
        return null;
    }

    void press(double x, double y);

    /** A press with Shift held: adds to what the press would pick (Select); the plain press elsewhere. */
    default void pressExtending(double x, double y) {
        press(x, y);
    }

    /** The pointer moved with the button down (only while a gesture of this tool is pending). */
    default void drag(double x, double y) {
    }

    /** The button went up (only while a gesture of this tool is pending). */
    default void release(double x, double y) {
    }

    /** A key (not a command shortcut) while this tool's step waits for one; true if used. */
    default boolean key(int keyCode) {
        return false;
    }

    /** What a click at (x, y) would act on, for the view to highlight. */
    default Optional<String> target(double x, double y) {
        return Optional.empty();
    }
}
