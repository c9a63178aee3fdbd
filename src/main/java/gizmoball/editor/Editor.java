package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.TriggerSource;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import physics.Vect;

/**
 * The board editor without Swing: pointer and key events in board coordinates (L) come in, board editing
 * operations go out. Each tool's handling is its own {@link ToolHandler}; what a tool has half done is one
 * {@link PendingStep}. Every change of the board goes through {@link Board}'s editing operations (the same ones
 * the file loader uses) inside the {@link EditHistory}, so the editor can build only boards the loader accepts,
 * and every edit can be undone. A refusal never escapes as an exception: its message goes to the status line.
 * <p>
 * Longer than 400 lines because it is the one facade of build mode (the state the views read, the menus' commands,
 * the services the handlers share); the work is in its parts: each tool's handler, the {@link Selection} and
 * {@link SelectionEdits}, {@link Picking}, {@link BuildKeys}, {@link PropertyEdits}, {@link ClipboardEdits} and
 * {@link LinkSteps}.
 */
public final class Editor {
    /** Dragging 1 L while placing a ball gives it 10 L/s: a board-wide drag is about the launch speed. */
    public static final double VELOCITY_PER_DRAG = 10;
    /** Names listed in a message before the rest are counted ("S1, S2, S3 and 5 more"). */
    private static final int LISTED = 4;

    private final Board board;
    private final EditHistory history;
    private final NameGenerator names;
    private final PropertyEdits properties = new PropertyEdits(this);
    private final ClipboardEdits clipboard = new ClipboardEdits(this);
    private final LinkSteps links = new LinkSteps(this);
    private final Selection selection;
    private final SelectionEdits selectionEdits;
    private final Picking picking;
    private final Map<Tool, ToolHandler> handlers = new EnumMap<>(Tool.class);
    private final List<Runnable> stateListeners = new ArrayList<>();
    private final List<Runnable> editListeners = new ArrayList<>();
    private String lastRefusal;
    private Consumer<String> messages = message -> { };

    private Tool tool = Tool.SELECT;
    private PendingStep step = PendingStep.NONE;
    private Preview preview;
    private Vect pointer;

    private Editor(Board board) {
        this.board = board;
        this.history = new EditHistory(board);
        this.names = new NameGenerator(board);
        this.selection = new Selection(board);
        this.selectionEdits = new SelectionEdits(this, selection);
        this.picking = new Picking(board);
    }

    /** An editor of {@code board}, with nothing selected and the Select tool. */
    public static Editor of(Board board) {
        Editor editor = new Editor(board);
        // Another board was opened: half-done steps and the selection belonged to the old one.
        editor.history.addResetListener(() -> {
            editor.selection.clear();
            editor.cancel();
        });
        return editor;
    }

    public Board board() {
        return board;
    }

    /** What the properties panel changes: constants, game, a gizmo's or a ball's values, names, links. */
    public PropertyEdits properties() {
        return properties;
    }

    /** The answers that complete Connect and Key Connect (what the target does, which edges of the key). */
    public LinkSteps links() {
        return links;
    }

    /** Copy, cut, paste and duplicate. */
    public ClipboardEdits clipboard() {
        return clipboard;
    }

    public EditHistory history() {
        return history;
    }

    /** Tells the player something about the editing (a view's own refusal, e.g. a field that is no number). */
    public void tell(String message) {
        say(message);
    }

    /**
     * Why the last edit that was refused was refused (the model's rule, a colour's syntax), for the field that
     * asked for it to show (see the properties panel's refused values).
     */
    public Optional<String> lastRefusal() {
        return Optional.ofNullable(lastRefusal);
    }

    /** Says why, and remembers it as the last refusal; false, for the caller to return. */
    boolean refuse(String reason) {
        lastRefusal = reason;
        say(reason);
        return false;
    }

    /** Where refusals and hints go (the status line). */
    public void setMessageSink(Consumer<String> sink) {
        this.messages = sink;
    }

    /** Called after every successful edit, undo and redo (to mark the session modified). */
    public void addEditListener(Runnable listener) {
        editListeners.add(listener);
    }

    /** Called whenever tool, selection, preview or the pending step changes (to repaint overlays and panels). */
    public void addStateListener(Runnable listener) {
        stateListeners.add(listener);
    }

    // ---- state for the views ----

    public Tool tool() {
        return tool;
    }

    /** What the current tool has half done. */
    public PendingStep step() {
        return step;
    }

    /**
     * Name of the selected gizmo or ball, or the outer walls' name; empty if nothing (still) exists. Of several
     * selected, the one selected last: the one whose connections and properties are shown.
     */
    public Optional<String> selected() {
        return selection.last();
    }

    /** Every selected gizmo and ball that (still) exists, in the order selected; the outer walls are not among them. */
    public List<String> selection() {
        return selection.things();
    }

    /** Whether more than one gizmo or ball is selected. */
    public boolean severalSelected() {
        return selection().size() > 1;
    }

    /** Whether the outer walls are selected (Select's click outside the board, or Connect's source there). */
    public boolean wallsSelected() {
        return selected().filter(Selection::isWalls).isPresent();
    }

    public Optional<Gizmo> selectedGizmo() {
        return selected().flatMap(board::gizmo);
    }

    public Optional<BallView> selectedBall() {
        return selected().flatMap(board::ball);
    }

    public Optional<Preview> preview() {
        return Optional.ofNullable(preview);
    }

    /** The handles of the one absorber selected with Select / Move, to drag for a new size; empty otherwise. */
    public List<Handle> handles() {
        if (tool != Tool.SELECT || step.isGesture() || severalSelected()) {
            return List.of();
        }
        return selectedGizmo().filter(g -> g.kind().sizedByCorners()).map(Handle::of).orElse(List.of());
    }

    /** The source chosen by the first click of Connect or Disconnect, waiting for the target. */
    public Optional<TriggerSource> connectSource() {
        return step instanceof PendingStep.ConnectingFrom c ? Optional.of(c.source()) : Optional.empty();
    }

    /** Where the pointer is over the board view, in L; empty when it is outside the view. */
    public Optional<Vect> pointer() {
        return Optional.ofNullable(pointer);
    }

    /**
     * What a click at the pointer would act on with the current tool (a gizmo, a ball or the outer walls), so
     * the view can highlight it before the click; empty for the placing tools or over nothing.
     */
    public Optional<String> target() {
        if (pointer == null || step.isGesture()) {
            return Optional.empty();
        }
        return handler().target(pointer.x(), pointer.y());
    }

    /** The gizmo Key Connect or Key Disconnect has, while it waits for a key to be pressed. */
    public Optional<String> awaitingKeyFor() {
        return step instanceof PendingStep.AwaitingKey k ? Optional.of(k.gizmo()) : Optional.empty();
    }

    /** True after Key Connect has its gizmo and key and waits for {@link LinkSteps#chooseEdges}. */
    public boolean awaitingEdge() {
        return step instanceof PendingStep.AwaitingEdge;
    }

    /** True after Connect has its source and target and waits for {@link LinkSteps#chooseConnection}. */
    public boolean awaitingAction() {
        return step instanceof PendingStep.AwaitingAction;
    }

    // ---- commands ----

    public void setTool(Tool newTool) {
        step = PendingStep.NONE;
        preview = null;
        tool = newTool;
        say(newTool.label() + ": " + newTool.hint());
        stateChanged();
    }

    /** Drops a half-done gesture or two-step command (Escape, switching to play). */
    public void cancel() {
        step = PendingStep.NONE;
        preview = null;
        stateChanged();
    }

    /** Selects the one gizmo, ball or the outer walls named, or nothing for null. */
    public void select(String name) {
        selectQuietly(name);
        stateChanged();
    }

    /** Shift+click: adds the gizmo or ball to the selection, or takes it out if it is in it. */
    public void toggleSelected(String name) {
        boolean added = selection.toggle(name);
        say((added ? "Added " + name : "Took out " + name) + ": " + selection.size() + " selected");
        stateChanged();
    }

    /** Selects these gizmos and balls (a rubber band, a paste), after what is selected if {@code adding}. */
    public void selectAll(List<String> names, boolean adding) {
        selection.addAll(names, adding);
        stateChanged();
    }

    public boolean undo() {
        return travel(history.undoable(), history::undo, "undo", "Undone: ");
    }

    public boolean redo() {
        return travel(history.redoable(), history::redo, "redo", "Redone: ");
    }

    /** Undo or redo: the step {@code what} names, taken by {@code take}, or a message that there is none. */
    private boolean travel(Optional<String> what, BooleanSupplier take, String verb, String done) {
        cancelQuietly();
        if (!take.getAsBoolean()) {
            say("Nothing to " + verb);
            return false;
        }
        say(done + what.orElseThrow());
        edited();
        return true;
    }

    /** Empties the board and resets gravity and friction; undoable (the view asks for confirmation first). */
    public boolean clearBoard() {
        cancelQuietly();
        selection.clear();
        return edit("Board cleared", Board::clear);
    }

    /** Deletes everything selected (one undo step). */
    public boolean deleteSelected() {
        return selectionEdits.deleteSelected();
    }

    /**
     * Turns the selected gizmo 90 degrees clockwise; of several selected, each that turns in its own cells (one undo
     * step; circles and absorbers look the same turned and stay).
     */
    public boolean rotateSelected() {
        return selectionEdits.rotateSelected();
    }

    // ---- pointer, in board coordinates ----

    /** The pointer moved with no button down: update the placement preview. */
    public void hover(double x, double y) {
        pointer = new Vect(x, y);
        if (!step.isGesture()) {
            setPreview(handler().hover(x, y), true);
        }
    }

    /** The pointer left the board view. */
    public void exit() {
        pointer = null;
        if (!step.isGesture()) {
            preview = null;
        }
        stateChanged();
    }

    public void press(double x, double y) {
        press(x, y, false);
    }

    /** A press; {@code extending} (Shift held) adds to the selection instead of replacing it (Select). */
    public void press(double x, double y, boolean extending) {
        if (extending) {
            handler().pressExtending(x, y);
        } else {
            handler().press(x, y);
        }
        stateChanged();
    }

    public void drag(double x, double y) {
        pointer = new Vect(x, y);
        if (step.isGesture()) {
            handler().drag(x, y);
        }
    }

    public void release(double x, double y) {
        if (step.isGesture()) {
            handler().release(x, y);
            stateChanged();
        }
    }

    /**
     * A key pressed over the board in build mode ({@link BuildKeys} says which do what).
     *
     * @return whether the key was used
     */
    public boolean keyPressed(int keyCode, boolean commandModifier) {
        return BuildKeys.pressed(this, keyCode, commandModifier);
    }

    /** The current tool took the key (a step waiting for one); false if it did not. */
    boolean keyToTool(int keyCode) {
        if (handler().key(keyCode)) {
            stateChanged();
            return true;
        }
        return false;
    }

    /**
     * Moves the selected gizmo one cell, or the selected ball a quarter cell, in the direction (dx, dy); several
     * selected move together (one undo step), by a cell, or a quarter cell if they are all balls.
     */
    public boolean nudgeSelected(int dx, int dy) {
        return selectionEdits.nudgeSelected(dx, dy);
    }

    /**
     * Selects the gizmo or ball at (x, y), or nothing where there is none (a context menu's target); one of several
     * selected keeps them all selected, for the menu to act on them all.
     */
    public boolean selectAt(double x, double y) {
        Optional<String> there = picking.ballOrGizmoAt(x, y);
        if (there.isPresent() && selection().contains(there.get())) {
            selection.bringToFront(there.get());
            stateChanged();
        } else {
            select(there.orElse(null));
        }
        return selected().isPresent();
    }

    /** Connect from here: the Connect tool with the selection as the source; the next click picks the target. */
    public void connectFromSelected() {
        links.startFromSelected();
    }

    /** "S1, C2 and T1", or for many "S1, C2, T1 and 5 more": the status line and the Edit menu stay short. */
    static String listed(List<String> names) {
        if (names.size() == 1) {
            return names.get(0);
        }
        boolean all = names.size() <= LISTED;
        List<String> head = names.subList(0, all ? names.size() - 1 : LISTED - 1);
        String rest = all ? names.get(names.size() - 1) : (names.size() - head.size()) + " more";
        return String.join(", ", head) + " and " + rest;
    }

    // ---- for the tool handlers ----

    NameGenerator names() {
        return names;
    }

    Picking picking() {
        return picking;
    }

    /** Delete, rotate and move of the selection and of what a gesture grabbed. */
    SelectionEdits selectionEdits() {
        return selectionEdits;
    }

    void setStep(PendingStep next) {
        step = next;
    }

    /** The press of a gesture is over: its step and its preview go. */
    void finishGesture() {
        step = PendingStep.NONE;
        preview = null;
    }

    /** Selects without telling the listeners yet (the handler's caller does, once the step is done). */
    void selectQuietly(String name) {
        selection.only(name);
    }

    boolean edit(String success, Consumer<Board> operation) {
        try {
            history.perform(success, operation);
        } catch (BoardEditException refused) {
            refuse(refused.getMessage());
            stateChanged();
            return false;
        }
        say(success);
        edited();
        return true;
    }

    Preview.Footprint footprint(GizmoKind kind, int x, int y, int width, int height) {
        return new Preview.Footprint(x, y, width, height, board.placementProblem(kind, x, y, width, height, null));
    }

    /** Asks the board itself (on a throw-away copy) whether an operation would be accepted. */
    Optional<String> dryRun(Consumer<Board> operation) {
        try {
            operation.accept(board.copy());
            return Optional.empty();
        } catch (BoardEditException refused) {
            return Optional.of(refused.getMessage());
        }
    }

    void setPreview(Preview next, boolean announce) {
        if (announce && next != null && next.problem().isPresent()
                && (preview == null || !next.problem().equals(preview.problem()))) {
            say(next.problem().get());
        }
        preview = next;
        stateChanged();
    }

    void say(String message) {
        messages.accept(message);
    }

    // ---- internals ----

    private ToolHandler handler() {
        return handlers.computeIfAbsent(tool, t -> ToolHandler.of(t, this));
    }

    private void cancelQuietly() {
        step = PendingStep.NONE;
        preview = null;
    }

    private void edited() {
        editListeners.forEach(Runnable::run);
        stateChanged();
    }

    void stateChanged() {
        stateListeners.forEach(Runnable::run);
    }
}
