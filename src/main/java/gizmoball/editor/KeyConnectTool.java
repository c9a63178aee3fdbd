package gizmoball.editor;

import gizmoball.boardfile.KeyCodes;
import gizmoball.model.KeyBinding;
import gizmoball.model.gizmo.Gizmo;
import java.awt.event.KeyEvent;
import java.util.List;
import java.util.Optional;

/**
 * Key Connect and Key Disconnect: click a gizmo, then press the key. Key Connect then asks for the edge
 * (the Down and Up arrows answer, as the view's popup does); Key Disconnect removes every edge of that key.
 */
final class KeyConnectTool implements ToolHandler {
    private final Editor editor;
    private final boolean bind;

    KeyConnectTool(Editor editor, boolean bind) {
        this.editor = editor;
        this.bind = bind;
    }

    @Override
    public Optional<String> target(double x, double y) {
        return editor.picking().gizmoAt(x, y).map(Gizmo::name);
    }

    @Override
    public void press(double x, double y) {
        editor.picking().gizmoAt(x, y).ifPresentOrElse(g -> {
            editor.selectQuietly(g.name());
            editor.setStep(new PendingStep.AwaitingKey(g.name()));
            editor.say(editor.tool().label() + ": now press the key for " + g.name());
        }, () -> editor.say("Click a gizmo first"));
    }

    @Override
    public boolean key(int keyCode) {
        PendingStep step = editor.step();
        if (step instanceof PendingStep.AwaitingEdge) {
            // Waiting for the edge: the arrows answer; other keys must not start something else meanwhile.
            if (keyCode == KeyEvent.VK_DOWN || keyCode == KeyEvent.VK_UP) {
                editor.links().chooseEdges(keyCode == KeyEvent.VK_DOWN ? EdgeChoice.DOWN : EdgeChoice.UP);
            }
            return true;
        }
        if (!(step instanceof PendingStep.AwaitingKey awaiting)) {
            return false;
        }
        String gizmo = awaiting.gizmo();
        if (bind) {
            editor.setStep(new PendingStep.AwaitingEdge(gizmo, keyCode));
            editor.say("Key " + KeyCodes.name(keyCode) + " for " + gizmo
                    + ": choose down (on press), up (on release) or both (hold), or press the Down or Up arrow");
        } else {
            unbind(gizmo, keyCode);
        }
        return true;
    }

    private void unbind(String gizmo, int keyCode) {
        List<KeyBinding> bindings = editor.board().keyBindings().stream()
                .filter(k -> k.gizmo().equals(gizmo) && k.keyCode() == keyCode).toList();
        editor.setStep(PendingStep.NONE);
        if (bindings.isEmpty()) {
            editor.say(gizmo + " has no binding for key " + KeyCodes.name(keyCode));
        } else {
            editor.edit("Unbound key " + KeyCodes.name(keyCode) + " from " + gizmo,
                    b -> bindings.forEach(k -> b.unbindKey(k.keyCode(), k.edge(), k.gizmo())));
        }
    }
}
