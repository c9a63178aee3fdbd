package gizmoball.editor;

import gizmoball.model.gizmo.Order;
import gizmoball.model.loop.TriggerSource;
import java.util.Optional;

/**
 * Connect and Disconnect: click the trigger source (a gizmo, or the outer walls), then the target; Connect then asks
 * what the target does (the view's popup, as Key Connect's) before it connects.
 */
final class ConnectTool implements ToolHandler {
    private final Editor editor;
    private final boolean connect;

    ConnectTool(Editor editor, boolean connect) {
        this.editor = editor;
        this.connect = connect;
    }

    @Override
    public Optional<String> target(double x, double y) {
        return end(x, y).map(TriggerSource::name);
    }

    /** The gizmo under the point, else the outer walls outside the board or on its rim. */
    private Optional<TriggerSource> end(double x, double y) {
        return editor.picking().gizmoAt(x, y).map(g -> TriggerSource.gizmo(g.name()))
                .or(() -> editor.picking().isWall(x, y) ? Optional.of(TriggerSource.OUTER_WALLS) : Optional.empty());
    }

    @Override
    public void press(double x, double y) {
        Optional<TriggerSource> end = end(x, y);
        if (end.isEmpty()) {
            editor.say("Click a gizmo, or outside the board for the outer walls");
            return;
        }
        if (!(editor.step() instanceof PendingStep.ConnectingFrom from)) {
            editor.selectQuietly(end.get().name());
            editor.setStep(new PendingStep.ConnectingFrom(end.get()));
            editor.say(editor.tool().label() + ": source " + end.get().name() + "; now click the gizmo it "
                    + (connect ? "should trigger" : "triggers"));
            return;
        }
        if (!(end.get() instanceof TriggerSource.OfGizmo target)) {
            editor.say("The outer walls can only be a trigger source: click a gizmo");
            return;
        }
        String name = target.gizmo();
        editor.setStep(PendingStep.NONE);
        if (connect) {
            editor.setStep(new PendingStep.AwaitingAction(from.source(), name, Order.DEFAULT));
            editor.say("Connect " + from.source() + " \u2192 " + name + ": choose what " + name + " does when "
                    + from.source() + " is hit, and after how long");
        } else {
            editor.properties().disconnect(from.source(), name);
        }
    }
}
