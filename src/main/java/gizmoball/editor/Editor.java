package gizmoball.editor;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.TriggerSource;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import physics.Vect;

/**
 * The board editor without Swing: pointer and key events in board coordinates (L) come in, board editing
 * operations go out. Each tool's handling is its own {@link ToolHandler}; what a tool has half done is one
 * {@link PendingStep}. Every change of the board goes through {@link Board}'s editing operations (the same ones
 * the file loader uses) inside the {@link EditHistory}, so the editor can build only boards the loader accepts,
 * and every edit can be undone. A refusal never escapes as an exception: its message goes to the status line.
 * <p>
 * Longer than 400 lines because it is the one facade of build mode: the state the views read, the commands of
 * the menus, and the services the handlers share (editing inside the history, previews, picking). What each tool
 * does is in its handler, what the properties panel changes in {@link PropertyEdits}, copy and paste in
 * {@link ClipboardEdits}, the answers that complete Connect and Key Connect in {@link LinkSteps}.
 */
public final class Editor {
    /** Ball centres snap to quarter cells: positions stay readable in saved files and easy to hit again. */
    static final double BALL_SNAP = 0.25;
    /** Pixels are coarse: a ball (radius 0.25 L) is picked within this distance of its centre. */
    static final double BALL_PICK_DISTANCE = 0.4;
    /** Clicks this close to the board's edge, on an empty cell, mean the outer walls (Connect tools). */
    static final double WALL_BAND = 0.25;
    /** Dragging 1 L while placing a ball gives it 10 L/s: a board-wide drag is about the launch speed. */
    public static final double VELOCITY_PER_DRAG = 10;
    /** Names listed in a message before the rest are counted ("S1, S2, S3 and 5 more"). */
    private static final int LISTED = 4;
    /** A press that moves less than this is a click, not a drag. */
    static final double DRAG_THRESHOLD = 0.1;

    private final Board board;
    private final EditHistory history;
    private final NameGenerator names;
    private final PropertyEdits properties = new PropertyEdits(this);
    private final ClipboardEdits clipboard = new ClipboardEdits(this);
    private final LinkSteps links = new LinkSteps(this);
    private final Map<Tool, ToolHandler> handlers = new EnumMap<>(Tool.class);
    private final List<Runnable> stateListeners = new ArrayList<>();
    private final List<Runnable> editListeners = new ArrayList<>();
    private String lastRefusal;
    private Consumer<String> messages = message -> { };

    private Tool tool = Tool.SELECT;
    /** What is selected, in the order it was selected: the last is the one the panels show (see {@link #selected}). */
    private final List<String> selection = new ArrayList<>();
    private PendingStep step = PendingStep.NONE;
    private Preview preview;
    private Vect pointer;

    private Editor(Board board) {
        this.board = board;
        this.history = new EditHistory(board);
        this.names = new NameGenerator(board);
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
        for (int i = selection.size() - 1; i >= 0; i--) {
            if (exists(selection.get(i))) {
                return Optional.of(selection.get(i));
            }
        }
        return Optional.empty();
    }

    /** Every selected gizmo and ball that (still) exists, in the order selected; the outer walls are not among them. */
    public List<String> selection() {
        return selection.stream().filter(n -> !isWalls(n) && exists(n)).toList();
    }

    /** Whether more than one gizmo or ball is selected. */
    public boolean severalSelected() {
        return selection().size() > 1;
    }

    private boolean exists(String name) {
        return isWalls(name) || board.gizmo(name).isPresent() || board.ball(name).isPresent();
    }

    /** Whether the outer walls are selected (Select's click outside the board, or Connect's source there). */
    public boolean wallsSelected() {
        return selected().filter(Editor::isWalls).isPresent();
    }

    private static boolean isWalls(String name) {
        return TriggerSource.named(name) instanceof TriggerSource.OuterWalls;
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
        selection.removeIf(Editor::isWalls);
        boolean added = !selection.remove(name);
        if (added) {
            selection.add(name);
        }
        say((added ? "Added " + name : "Took out " + name) + ": " + selection.size() + " selected");
        stateChanged();
    }

    /** Selects these gizmos and balls (a rubber band, a paste), after what is selected if {@code adding}. */
    public void selectAll(List<String> names, boolean adding) {
        if (!adding) {
            selection.clear();
        }
        selection.removeIf(Editor::isWalls);
        names.stream().filter(n -> !selection.contains(n)).forEach(selection::add);
        stateChanged();
    }

    public boolean undo() {
        cancelQuietly();
        Optional<String> what = history.undoable();
        if (!history.undo()) {
            say("Nothing to undo");
            return false;
        }
        say("Undone: " + what.orElseThrow());
        edited();
        return true;
    }

    public boolean redo() {
        cancelQuietly();
        Optional<String> what = history.redoable();
        if (!history.redo()) {
            say("Nothing to redo");
            return false;
        }
        say("Redone: " + what.orElseThrow());
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
        List<String> names = selection();
        if (names.isEmpty()) {
            say("Nothing selected to delete");
            return false;
        }
        return names.size() == 1 ? delete(names.get(0)) : deleteAll("Deleted ", names);
    }

    /**
     * Turns the selected gizmo 90 degrees clockwise; of several selected, each that turns in its own cells (one undo
     * step; circles and absorbers look the same turned and stay).
     */
    public boolean rotateSelected() {
        List<Gizmo> gizmos = selection().stream().flatMap(n -> board.gizmo(n).stream()).toList();
        if (gizmos.isEmpty()) {
            say("Select a gizmo to rotate");
            return false;
        }
        if (gizmos.size() == 1) {
            return rotate(gizmos.get(0));
        }
        List<String> turning = gizmos.stream().filter(g -> g.kind().rotates()).map(Gizmo::name).toList();
        if (turning.isEmpty()) {
            return refuse("Circles and absorbers look the same turned: none of the selection can be rotated");
        }
        return edit("Rotated " + listed(turning), b -> turning.forEach(b::rotate));
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

    // ---- keys ----

    /**
     * A key pressed over the board in build mode. A step waiting for a key (Key Connect, Key Disconnect) takes
     * any key but Escape (which cancels) and Ctrl/Alt/Meta combinations (which belong to the menus, e.g. Ctrl+Z
     * while waiting). Otherwise Delete removes the selection, the arrow keys nudge it and the tool shortcuts
     * switch tools.
     *
     * @return whether the key was used
     */
    public boolean keyPressed(int keyCode, boolean commandModifier) {
        if (keyCode == KeyEvent.VK_ESCAPE) {
            cancel();
            say("Cancelled");
            return true;
        }
        if (commandModifier) {
            return false;
        }
        if (handler().key(keyCode)) {
            stateChanged();
            return true;
        }
        switch (keyCode) {
            case KeyEvent.VK_DELETE, KeyEvent.VK_BACK_SPACE -> deleteSelected();
            case KeyEvent.VK_LEFT -> nudgeSelected(-1, 0);
            case KeyEvent.VK_RIGHT -> nudgeSelected(1, 0);
            case KeyEvent.VK_UP -> nudgeSelected(0, -1);
            case KeyEvent.VK_DOWN -> nudgeSelected(0, 1);
            default -> {
                Optional<Tool> shortcut = Tool.forShortcut(keyCode);
                shortcut.ifPresent(this::setTool);
                return shortcut.isPresent();
            }
        }
        return true;
    }

    /**
     * Moves the selected gizmo one cell, or the selected ball a quarter cell, in the direction (dx, dy); several
     * selected move together (one undo step), by a cell, or a quarter cell if they are all balls.
     */
    public boolean nudgeSelected(int dx, int dy) {
        List<String> group = selection();
        if (group.size() > 1) {
            double step = group.stream().anyMatch(n -> board.gizmo(n).isPresent()) ? 1 : BALL_SNAP;
            return moveGroup(group, dx * step, dy * step);
        }
        Optional<Gizmo> gizmo = selectedGizmo();
        Optional<BallView> ball = selectedBall();
        if (gizmo.isPresent()) {
            Gizmo g = gizmo.get();
            int x = g.x() + dx;
            int y = g.y() + dy;
            return edit("Moved " + g.name() + " to (" + x + "," + y + ")", b -> b.moveGizmo(g.name(), x, y));
        }
        if (ball.isPresent()) {
            BallView b0 = ball.get();
            double x = b0.position().x() + dx * BALL_SNAP;
            double y = b0.position().y() + dy * BALL_SNAP;
            return edit("Moved " + b0.name() + " to (" + x + ", " + y + ")", b -> b.moveBall(b0.name(), x, y));
        }
        say("Select a gizmo or ball to move it with the arrow keys");
        return false;
    }

    /**
     * Selects the gizmo or ball at (x, y), or nothing where there is none (a context menu's target); one of several
     * selected keeps them all selected, for the menu to act on them all.
     */
    public boolean selectAt(double x, double y) {
        Optional<String> there = ballOrGizmoAt(x, y);
        if (there.isPresent() && selection().contains(there.get())) {
            selection.remove(there.get());
            selection.add(there.get());
            stateChanged();
        } else {
            select(there.orElse(null));
        }
        return selected().isPresent();
    }

    /** Connect from here: the Connect tool with the selection as the source; the next click picks the target. */
    public void connectFromSelected() {
        Optional<String> source = selectedGizmo().map(Gizmo::name).or(() -> selected().filter(Editor::isWalls));
        if (source.isEmpty()) {
            say("Select a gizmo to connect from it");
            return;
        }
        setTool(Tool.CONNECT);
        step = new PendingStep.ConnectingFrom(TriggerSource.named(source.get()));
        say("Connect from " + source.get() + ": click the gizmo it triggers (Esc cancels)");
        stateChanged();
    }

    /**
     * Deletes the named gizmos and balls as one undo step: the balls first, since an absorber takes the balls it
     * holds with it.
     */
    boolean deleteAll(String verb, List<String> names) {
        List<String> ordered = new ArrayList<>(names);
        ordered.sort(Comparator.comparing((String n) -> board.ball(n).isEmpty()));
        boolean done = edit(verb + listed(names), b -> ordered.forEach(b::delete));
        if (done) {
            selection.clear();
            stateChanged();
        }
        return done;
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

    /** A distance as a message shows it: 2, not 2.0; 0.25 as it is. */
    private static String brief(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }

    // ---- for the tool handlers ----

    NameGenerator names() {
        return names;
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
        selection.clear();
        if (name != null) {
            selection.add(name);
        }
    }

    /** Moves the named gizmos and balls together by (dx, dy) L (one undo step); no move is no edit. */
    boolean moveGroup(List<String> names, double dx, double dy) {
        if (dx == 0 && dy == 0) {
            return true;
        }
        return edit("Moved " + listed(names) + " by (" + brief(dx) + "," + brief(dy) + ")",
                b -> b.moveGroup(names, dx, dy));
    }

    /**
     * Turns a gizmo 90 degrees clockwise. A kind that looks the same turned (a circle, an absorber:
     * {@link GizmoKind#rotates}) is refused with a message and leaves no undo step, rather than "rotating" with
     * nothing to see.
     */
    boolean rotate(Gizmo gizmo) {
        if (!gizmo.kind().rotates()) {
            say(gizmo.name() + " is " + gizmo.kind().withArticle()
                    + ": it looks the same turned, so it cannot be rotated");
            stateChanged();
            return false;
        }
        return edit("Rotated " + gizmo.name(), b -> b.rotate(gizmo.name()));
    }

    boolean delete(String name) {
        selection.remove(name);
        return edit("Deleted " + name, b -> b.delete(name));
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

    Optional<Gizmo> gizmoAt(double x, double y) {
        return board.gizmoAt(cell(x), cell(y));
    }

    Optional<BallView> ballNear(double x, double y) {
        return board.balls().stream()
                .filter(b -> Math.hypot(b.position().x() - x, b.position().y() - y) <= BALL_PICK_DISTANCE)
                .min(Comparator.comparingDouble(b -> Math.hypot(b.position().x() - x, b.position().y() - y)));
    }

    /** The name of the ball or else the gizmo under the point: a ball first, as it may sit on a gizmo's cell. */
    Optional<String> ballOrGizmoAt(double x, double y) {
        return ballNear(x, y).map(BallView::name).or(() -> gizmoAt(x, y).map(Gizmo::name));
    }

    boolean isWall(double x, double y) {
        boolean outside = x < 0 || y < 0 || x >= Board.SIZE || y >= Board.SIZE;
        boolean nearEdge = x < WALL_BAND || y < WALL_BAND || x > Board.SIZE - WALL_BAND || y > Board.SIZE - WALL_BAND;
        return outside || (nearEdge && gizmoAt(x, y).isEmpty());
    }

    void say(String message) {
        messages.accept(message);
    }

    static int cell(double v) {
        return (int) Math.floor(v);
    }

    static double snap(double v) {
        return Math.round(v / BALL_SNAP) * BALL_SNAP;
    }

    // ---- internals ----

    private ToolHandler handler() {
        return handlers.computeIfAbsent(tool, this::newHandler);
    }

    private ToolHandler newHandler(Tool t) {
        return switch (t) {
            case ABSORBER -> new PlaceAbsorberTool(this);
            case BALL -> new PlaceBallTool(this);
            case SELECT -> new SelectTool(this);
            case ROTATE -> new RotateTool(this);
            case DELETE -> new DeleteTool(this);
            case CONNECT -> new ConnectTool(this, true);
            case DISCONNECT -> new ConnectTool(this, false);
            case KEY_CONNECT -> new KeyConnectTool(this, true);
            case KEY_DISCONNECT -> new KeyConnectTool(this, false);
            // Every other tool places a gizmo of its kind on one cell.
            default -> new PlaceGizmoTool(this, t.kind().orElseThrow());
        };
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
