package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.Gizmo;
import java.util.Optional;

/** Connect and Disconnect: click the trigger source (a gizmo, or the outer walls), then the target. */
final class ConnectTool implements ToolHandler {
    private final Editor editor;
    private final boolean connect;

    ConnectTool(Editor editor, boolean connect) {
        this.editor = editor;
        this.connect = connect;
    }

    @Override
    public Optional<String> target(double x, double y) {
        return editor.gizmoAt(x, y).map(Gizmo::name)
                .or(() -> editor.isWall(x, y) ? Optional.of(Board.OUTER_WALLS) : Optional.empty());
    }

    @Override
    public void press(double x, double y) {
        Optional<String> end = target(x, y);
        if (end.isEmpty()) {
            editor.say("Click a gizmo, or outside the board for the outer walls");
            return;
        }
        String name = end.get();
        if (!(editor.step() instanceof PendingStep.ConnectingFrom from)) {
            editor.selectQuietly(name);
            editor.setStep(new PendingStep.ConnectingFrom(name));
            editor.say(editor.tool().label() + ": source " + name + "; now click the gizmo it "
                    + (connect ? "should trigger" : "triggers"));
            return;
        }
        if (name.equals(Board.OUTER_WALLS)) {
            editor.say("The outer walls can only be a trigger source: click a gizmo");
            return;
        }
        editor.setStep(PendingStep.NONE);
        if (connect) {
            editor.edit("Connected " + from.source() + " -> " + name, b -> b.connect(from.source(), name));
        } else {
            editor.disconnect(from.source(), name);
        }
    }
}
