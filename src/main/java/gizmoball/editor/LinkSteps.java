package gizmoball.editor;

import gizmoball.boardfile.KeyCodes;
import gizmoball.boardfile.OrderWords;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.loop.TriggerSource;
import java.util.List;
import java.util.Optional;

/**
 * The second half of Connect and Key Connect: once the tool has its source and target (or its gizmo and key), the
 * popup's answers (what the target is told to do and after how long, which edges of the key) complete the pending
 * step as one undo step of its editor.
 */
public final class LinkSteps {
    private final Editor editor;

    LinkSteps(Editor editor) {
        this.editor = editor;
    }

    /**
     * Completes Key Connect: binds the pending key's chosen edges to the gizmo with the pending order, its action
     * (empty: as each edge drives it unless told) and delay (one undo step; the board refuses an action the gizmo
     * lacks).
     */
    public boolean chooseEdges(EdgeChoice choice) {
        if (!(editor.step() instanceof PendingStep.AwaitingEdge pending)) {
            editor.say("Key Connect: click a gizmo and press a key first");
            return false;
        }
        List<KeyBinding> bindings = choice.edges().stream()
                .map(edge -> new KeyBinding(pending.keyCode(), edge, pending.gizmo(), pending.order())).toList();
        editor.setStep(PendingStep.NONE);
        String what = bindings.size() == 1 ? KeyCodes.describe(bindings.get(0))
                : "key " + KeyCodes.name(pending.keyCode()) + " down and up \u2192 " + pending.gizmo();
        boolean done = editor.edit("Bound " + what,
                b -> bindings.forEach(k -> b.bindKey(k.keyCode(), k.edge(), k.gizmo(), k.order())));
        editor.stateChanged();
        return done;
    }

    /** {@link #chooseEdges} with one edge. */
    public boolean chooseEdge(KeyEdge edge) {
        return chooseEdges(edge == KeyEdge.DOWN ? EdgeChoice.DOWN : EdgeChoice.UP);
    }

    /**
     * What Key Connect's binding or Connect's connection will make its gizmo do, and after how long, once it is
     * made.
     */
    public void orderPending(Order order) {
        if (editor.step() instanceof PendingStep.AwaitingEdge pending) {
            editor.setStep(new PendingStep.AwaitingEdge(pending.gizmo(), pending.keyCode(), order));
        } else if (editor.step() instanceof PendingStep.AwaitingAction pending) {
            editor.setStep(new PendingStep.AwaitingAction(pending.source(), pending.target(), order));
        }
    }

    /** Completes Connect: connects the pending source to the target with the pending order (one undo step). */
    public boolean chooseConnection() {
        if (!(editor.step() instanceof PendingStep.AwaitingAction pending)) {
            editor.say("Connect: click the source, then the gizmo it triggers, first");
            return false;
        }
        editor.setStep(PendingStep.NONE);
        boolean done = editor.edit("Connected " + pending.source() + " \u2192 " + pending.target()
                + OrderWords.of(pending.order()), b -> b.connect(pending.source(), pending.target(), pending.order()));
        editor.stateChanged();
        return done;
    }

    /**
     * The kind of the gizmo the pending step will drive (Key Connect awaiting its edge, Connect its action), whose
     * actions the popup
     * offers; empty when no such answer is awaited.
     */
    public Optional<GizmoKind> awaitedTargetKind() {
        if (editor.step() instanceof PendingStep.AwaitingEdge pending) {
            return editor.board().gizmo(pending.gizmo()).map(Gizmo::kind);
        }
        if (editor.step() instanceof PendingStep.AwaitingAction pending) {
            return editor.board().gizmo(pending.target()).map(Gizmo::kind);
        }
        return Optional.empty();
    }

    /** Connect from the selection (a gizmo or the outer walls): the Connect tool, waiting for the target. */
    void startFromSelected() {
        Optional<String> source = editor.selectedGizmo().map(Gizmo::name)
                .or(() -> editor.selected().filter(Selection::isWalls));
        if (source.isEmpty()) {
            editor.say("Select a gizmo to connect from it");
            return;
        }
        editor.setTool(Tool.CONNECT);
        editor.setStep(new PendingStep.ConnectingFrom(TriggerSource.named(source.get())));
        editor.say("Connect from " + source.get() + ": click the gizmo it triggers (Esc cancels)");
        editor.stateChanged();
    }
}
