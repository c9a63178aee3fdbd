package gizmoball.editor;

import gizmoball.model.Ball;
import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.Gizmo;
import gizmoball.model.GizmoKind;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.Rgb;
import physics.Vect;

import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.function.Consumer;
import java.util.regex.Pattern;

/**
 * The board editor without Swing: pointer and key events in board coordinates (L) come in, board editing
 * operations go out. Every change of the board goes through {@link Board}'s editing operations (the same ones
 * the file loader uses) inside the {@link EditHistory}, so the editor can build only boards the loader accepts,
 * and every edit can be undone. A refusal never escapes as an exception: its message goes to the status line.
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
    private static final Pattern HEX_COLOUR = Pattern.compile("[0-9a-fA-F]{6}");
    /** A Select press that moves less than this is a click, not a move. */
    static final double DRAG_THRESHOLD = 0.1;

    private final Board board;
    private final EditHistory history;
    private final NameGenerator names;
    private final List<Runnable> stateListeners = new ArrayList<>();
    private final List<Runnable> editListeners = new ArrayList<>();
    private Consumer<String> messages = message -> { };

    private Tool tool = Tool.SELECT;
    private String selected;
    private Preview preview;
    private Gesture gesture;
    private String connectSource;
    private String keyGizmo;
    private Integer pendingKey;
    private Vect pointer;

    /** A press that is not finished yet: what the following drags and the release act on. */
    private sealed interface Gesture {
        record AbsorberDrag(int x0, int y0) implements Gesture { }
        record BallDrag(double x, double y, double pressX, double pressY) implements Gesture { }
        record GizmoMove(Gizmo gizmo, int grabDx, int grabDy) implements Gesture { }
        record BallMove(Ball ball, double pressX, double pressY) implements Gesture { }
    }

    public Editor(Board board) {
        this.board = board;
        this.history = new EditHistory(board);
        this.names = new NameGenerator(board);
        // Another board was opened: half-done steps and the selection belonged to the old one.
        history.addResetListener(() -> {
            selected = null;
            cancel();
        });
    }

    public Board board() {
        return board;
    }

    public EditHistory history() {
        return history;
    }

    /** Where refusals and hints go (the status line). */
    public void setMessageSink(Consumer<String> sink) {
        this.messages = sink;
    }

    /** Called after every successful edit, undo and redo (to mark the session modified). */
    public void addEditListener(Runnable listener) {
        editListeners.add(listener);
    }

    /** Called whenever tool, selection, preview or a pending step changes (to repaint overlays and panels). */
    public void addStateListener(Runnable listener) {
        stateListeners.add(listener);
    }

    // ---- state for the views ----

    public Tool tool() {
        return tool;
    }

    /** Name of the selected gizmo or ball, or {@link Board#OUTER_WALLS}; empty if nothing (still) exists. */
    public Optional<String> selected() {
        if (selected == null) {
            return Optional.empty();
        }
        boolean exists = selected.equals(Board.OUTER_WALLS)
                || board.gizmo(selected).isPresent() || board.ball(selected).isPresent();
        return exists ? Optional.of(selected) : Optional.empty();
    }

    public Optional<Gizmo> selectedGizmo() {
        return selected().flatMap(board::gizmo);
    }

    public Optional<Ball> selectedBall() {
        return selected().flatMap(board::ball);
    }

    public Optional<Preview> preview() {
        return Optional.ofNullable(preview);
    }

    /** The source chosen by the first click of Connect or Disconnect, waiting for the target. */
    public Optional<String> connectSource() {
        return Optional.ofNullable(connectSource);
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
        if (pointer == null || gesture != null) {
            return Optional.empty();
        }
        double x = pointer.x();
        double y = pointer.y();
        Optional<String> gizmo = gizmoAt(x, y).map(Gizmo::name);
        return switch (tool) {
            case SELECT, DELETE -> ballNear(x, y).map(Ball::name).or(() -> gizmo);
            case ROTATE, KEY_CONNECT, KEY_DISCONNECT -> gizmo;
            case CONNECT, DISCONNECT -> gizmo.or(() -> isWall(x, y) ? Optional.of(Board.OUTER_WALLS)
                    : Optional.empty());
            default -> Optional.empty();
        };
    }

    /** The gizmo Key Connect or Key Disconnect has, while it waits for a key to be pressed. */
    public Optional<String> awaitingKeyFor() {
        return pendingKey == null ? Optional.ofNullable(keyGizmo) : Optional.empty();
    }

    /** True after Key Connect has its gizmo and key and waits for {@link #chooseEdge}. */
    public boolean awaitingEdge() {
        return pendingKey != null;
    }

    // ---- commands ----

    public void setTool(Tool newTool) {
        resetSteps();
        tool = newTool;
        say(newTool.label() + ": " + newTool.hint());
        stateChanged();
    }

    /** Drops a half-done gesture or two-step command (Escape, switching to play). */
    public void cancel() {
        resetSteps();
        stateChanged();
    }

    public void select(String name) {
        selected = name;
        stateChanged();
    }

    public boolean undo() {
        resetSteps();
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
        resetSteps();
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
        resetSteps();
        selected = null;
        return edit("Board cleared", Board::clear);
    }

    public boolean deleteSelected() {
        Optional<String> name = selected().filter(n -> !n.equals(Board.OUTER_WALLS));
        if (name.isEmpty()) {
            say("Nothing selected to delete");
            return false;
        }
        return delete(name.get());
    }

    public boolean rotateSelected() {
        Optional<Gizmo> gizmo = selectedGizmo();
        if (gizmo.isEmpty()) {
            say("Select a gizmo to rotate");
            return false;
        }
        return edit("Rotated " + gizmo.get().name(), b -> b.rotate(gizmo.get().name()));
    }

    /** Sets gravity and friction together from text fields (one undo step); unchanged values are no edit. */
    public boolean setConstants(String gravityText, String muText, String mu2Text) {
        OptionalDouble g = number("Gravity", gravityText);
        OptionalDouble mu = g.isPresent() ? number("mu", muText) : OptionalDouble.empty();
        OptionalDouble mu2 = mu.isPresent() ? number("mu2", mu2Text) : OptionalDouble.empty();
        if (mu2.isEmpty()) {
            return false;
        }
        double gv = g.getAsDouble();
        double muv = mu.getAsDouble();
        double mu2v = mu2.getAsDouble();
        if (gv == board.gravity() && muv == board.mu() && mu2v == board.mu2()) {
            return true;
        }
        return edit("Gravity " + gv + " L/s\u00b2, friction mu " + muv + "/s, mu2 " + mu2v + "/L", b -> {
            b.setGravity(gv);
            b.setFriction(muv, mu2v);
        });
    }

    /**
     * Sets the selected ball's centre and velocity from text fields. The board has no "set velocity" operation,
     * so a velocity change re-adds the ball under the same name; the history makes the pair atomic.
     */
    public boolean setBall(String name, String xText, String yText, String vxText, String vyText) {
        Optional<Ball> ball = board.ball(name);
        if (ball.isEmpty()) {
            say("No ball named " + name);
            return false;
        }
        double[] v = new double[4];
        String[] labels = {"x", "y", "vx", "vy"};
        String[] texts = {xText, yText, vxText, vyText};
        for (int i = 0; i < v.length; i++) {
            OptionalDouble d = number(labels[i], texts[i]);
            if (d.isEmpty()) {
                return false;
            }
            v[i] = d.getAsDouble();
        }
        Ball b0 = ball.get();
        boolean sameVelocity = b0.velocity().x() == v[2] && b0.velocity().y() == v[3];
        if (sameVelocity && b0.position().x() == v[0] && b0.position().y() == v[1]) {
            return true;
        }
        return edit("Ball " + name + " updated", b -> {
            if (sameVelocity) {
                b.moveBall(name, v[0], v[1]);
            } else {
                b.delete(name);
                b.addBall(name, v[0], v[1], v[2], v[3]);
            }
        });
    }

    /**
     * Gives a gizmo its own colour from text: {@code #rrggbb} (the # optional), or empty for its kind's colour.
     * One undo step; the same colour again is no edit.
     */
    public boolean setColour(String gizmo, String text) {
        Optional<Gizmo> target = board.gizmo(gizmo);
        if (target.isEmpty()) {
            say("No gizmo named " + gizmo);
            return false;
        }
        String hex = text.strip();
        hex = hex.startsWith("#") ? hex.substring(1) : hex;
        Optional<Rgb> colour;
        if (hex.isEmpty()) {
            colour = Optional.empty();
        } else if (HEX_COLOUR.matcher(hex).matches()) {
            colour = Optional.of(Rgb.of(Integer.parseInt(hex, 16)));
        } else {
            say("Colour '" + text.strip() + "' is not #rrggbb (such as #99b3ff); leave it empty for the "
                    + "colour of the kind");
            return false;
        }
        if (colour.equals(target.get().colour())) {
            return true;
        }
        return edit(colour.map(c -> gizmo + " coloured " + hex(c)).orElse(gizmo + " back to the colour of its kind"),
                b -> b.setColour(gizmo, colour));
    }

    /** {@code #rrggbb}, as the properties panel shows a colour. */
    public static String hex(Rgb colour) {
        return String.format(Locale.ROOT, "#%06x", colour.packed());
    }

    /** Removes one connection (from the properties panel's list). */
    public boolean disconnect(String source, String target) {
        return edit("Disconnected " + source + " -> " + target, b -> b.disconnect(source, target));
    }

    /** Removes one key binding (from the properties panel's list). */
    public boolean unbind(KeyBinding binding) {
        return edit("Removed " + describe(binding),
                b -> b.unbindKey(binding.keyCode(), binding.edge(), binding.gizmo()));
    }

    // ---- pointer, in board coordinates ----

    /** The pointer moved with no button down: update the placement preview. */
    public void hover(double x, double y) {
        pointer = new Vect(x, y);
        if (gesture != null) {
            return;
        }
        setPreview(switch (tool) {
            case SQUARE, CIRCLE, TRIANGLE, LEFT_FLIPPER, RIGHT_FLIPPER -> footprint(tool.kind().orElseThrow(),
                    cell(x), cell(y));
            case ABSORBER -> absorberFootprint(cell(x), cell(y), cell(x), cell(y));
            case BALL -> ballPlacement(snap(x), snap(y), 0, 0);
            default -> null;
        }, true);
    }

    /** The pointer left the board view. */
    public void exit() {
        pointer = null;
        if (gesture == null) {
            setPreview(null, false);
        }
        stateChanged();
    }

    public void press(double x, double y) {
        switch (tool) {
            case SQUARE, CIRCLE, TRIANGLE, LEFT_FLIPPER, RIGHT_FLIPPER ->
                    placeGizmo(tool.kind().orElseThrow(), cell(x), cell(y));
            case ABSORBER -> {
                gesture = new Gesture.AbsorberDrag(cell(x), cell(y));
                drag(x, y);
            }
            case BALL -> {
                gesture = new Gesture.BallDrag(snap(x), snap(y), x, y);
                drag(x, y);
            }
            case SELECT -> pressSelect(x, y);
            case ROTATE -> gizmoAt(x, y).ifPresentOrElse(g -> {
                selected = g.name();
                edit("Rotated " + g.name(), b -> b.rotate(g.name()));
            }, () -> say("No gizmo here to rotate"));
            case DELETE -> {
                Optional<String> name = ballNear(x, y).map(Ball::name).or(() -> gizmoAt(x, y).map(Gizmo::name));
                name.ifPresentOrElse(this::delete, () -> say("Nothing here to delete"));
            }
            case CONNECT, DISCONNECT -> pressConnect(x, y);
            case KEY_CONNECT, KEY_DISCONNECT -> gizmoAt(x, y).ifPresentOrElse(g -> {
                keyGizmo = g.name();
                pendingKey = null;
                selected = g.name();
                say(tool.label() + ": now press the key for " + g.name());
                stateChanged();
            }, () -> say("Click a gizmo first"));
        }
    }

    public void drag(double x, double y) {
        pointer = new Vect(x, y);
        if (gesture instanceof Gesture.AbsorberDrag a) {
            setPreview(absorberFootprint(a.x0(), a.y0(), cell(x), cell(y)), true);
        } else if (gesture instanceof Gesture.BallDrag b) {
            // Measured from where the button went down, not from the snapped centre: a click is no velocity.
            boolean still = Math.hypot(x - b.pressX(), y - b.pressY()) < DRAG_THRESHOLD;
            setPreview(still ? ballPlacement(b.x(), b.y(), 0, 0)
                    : ballPlacement(b.x(), b.y(), velocity(x - b.pressX()), velocity(y - b.pressY())), true);
        } else if (gesture instanceof Gesture.GizmoMove m) {
            Gizmo g = m.gizmo();
            int tx = cell(x) - m.grabDx();
            int ty = cell(y) - m.grabDy();
            setPreview(new Preview.Footprint(tx, ty, g.width(), g.height(),
                    board.placementProblem(g.kind(), tx, ty, g.width(), g.height(), g.name())), true);
        } else if (gesture instanceof Gesture.BallMove m) {
            if (!isDrag(m, x, y)) {
                setPreview(null, false);
                return;
            }
            double tx = ballMoveTarget(m.ball().position().x(), m.pressX(), x);
            double ty = ballMoveTarget(m.ball().position().y(), m.pressY(), y);
            String name = m.ball().name();
            setPreview(new Preview.BallPlacement(tx, ty, m.ball().velocity().x(), m.ball().velocity().y(),
                    dryRun(b -> b.moveBall(name, tx, ty))), true);
        }
    }

    public void release(double x, double y) {
        if (gesture == null) {
            return;
        }
        drag(x, y);
        Gesture finished = gesture;
        Preview last = preview;
        gesture = null;
        preview = null;
        if (finished instanceof Gesture.AbsorberDrag && last instanceof Preview.Footprint f) {
            String name = names.nextGizmoName(GizmoKind.ABSORBER);
            if (edit("Placed absorber " + name, b -> b.addAbsorber(name, f.x(), f.y(),
                    f.x() + f.width(), f.y() + f.height()))) {
                selected = name;
            }
        } else if (finished instanceof Gesture.BallDrag && last instanceof Preview.BallPlacement p) {
            String name = names.nextBallName();
            if (edit("Placed ball " + name + " moving at (" + p.vx() + ", " + p.vy() + ") L/s",
                    b -> b.addBall(name, p.x(), p.y(), p.vx(), p.vy()))) {
                selected = name;
            }
        } else if (finished instanceof Gesture.GizmoMove m && last instanceof Preview.Footprint f) {
            Gizmo g = m.gizmo();
            if (f.x() != g.x() || f.y() != g.y()) {
                edit("Moved " + g.name() + " to (" + f.x() + "," + f.y() + ")",
                        b -> b.moveGizmo(g.name(), f.x(), f.y()));
            }
        } else if (finished instanceof Gesture.BallMove m && last instanceof Preview.BallPlacement p) {
            edit("Moved " + m.ball().name() + " to (" + p.x() + ", " + p.y() + ")",
                    b -> b.moveBall(m.ball().name(), p.x(), p.y()));
        }
        stateChanged();
    }

    // ---- keys ----

    /**
     * A key pressed over the board in build mode. Key Connect / Key Disconnect waiting for a key take any key
     * but Escape (which cancels) and Ctrl/Alt/Meta combinations (which belong to the menus, e.g. Ctrl+Z while
     * waiting). Otherwise Delete removes the selection, the arrow keys nudge it and the tool shortcuts switch
     * tools.
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
        if (pendingKey != null) {
            // Waiting for down or up: the arrow keys answer; other keys must not start something else meanwhile.
            if (keyCode == KeyEvent.VK_DOWN || keyCode == KeyEvent.VK_UP) {
                chooseEdge(keyCode == KeyEvent.VK_DOWN ? KeyEdge.DOWN : KeyEdge.UP);
            }
            return true;
        }
        if (keyGizmo != null) {
            if (tool == Tool.KEY_CONNECT) {
                pendingKey = keyCode;
                say("Key " + KeyEvent.getKeyText(keyCode) + " for " + keyGizmo
                        + ": choose down (on press) or up (on release), or press the Down or Up arrow");
                stateChanged();
            } else {
                unbindKey(keyGizmo, keyCode);
            }
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

    /** Moves the selected gizmo one cell, or the selected ball a quarter cell, in the direction (dx, dy). */
    public boolean nudgeSelected(int dx, int dy) {
        Optional<Gizmo> gizmo = selectedGizmo();
        Optional<Ball> ball = selectedBall();
        if (gizmo.isPresent()) {
            Gizmo g = gizmo.get();
            int x = g.x() + dx;
            int y = g.y() + dy;
            return edit("Moved " + g.name() + " to (" + x + "," + y + ")", b -> b.moveGizmo(g.name(), x, y));
        }
        if (ball.isPresent()) {
            Ball b0 = ball.get();
            double x = b0.position().x() + dx * BALL_SNAP;
            double y = b0.position().y() + dy * BALL_SNAP;
            return edit("Moved " + b0.name() + " to (" + x + ", " + y + ")", b -> b.moveBall(b0.name(), x, y));
        }
        say("Select a gizmo or ball to move it with the arrow keys");
        return false;
    }

    /** Completes Key Connect: binds the pending key's down or up edge to the gizmo. */
    public boolean chooseEdge(KeyEdge edge) {
        if (pendingKey == null || keyGizmo == null) {
            say("Key Connect: click a gizmo and press a key first");
            return false;
        }
        KeyBinding binding = new KeyBinding(pendingKey, edge, keyGizmo);
        resetSteps();
        boolean done = edit("Bound " + describe(binding),
                b -> b.bindKey(binding.keyCode(), binding.edge(), binding.gizmo()));
        stateChanged();
        return done;
    }

    public static String describe(KeyBinding binding) {
        return "key " + KeyEvent.getKeyText(binding.keyCode()) + " " + binding.edge().name().toLowerCase()
                + " \u2192 " + binding.gizmo();
    }

    // ---- the tools' steps ----

    private void placeGizmo(GizmoKind kind, int x, int y) {
        String name = names.nextGizmoName(kind);
        if (edit("Placed " + name + " at (" + x + "," + y + ")", b -> b.addGizmo(kind, name, x, y))) {
            selected = name;
        }
        // The cell is now taken: refresh the preview without announcing the overlap over the success message.
        setPreview(footprint(kind, x, y), false);
    }

    private void pressSelect(double x, double y) {
        Optional<Ball> ball = ballNear(x, y);
        Optional<Gizmo> gizmo = gizmoAt(x, y);
        if (ball.isPresent()) {
            selected = ball.get().name();
            gesture = new Gesture.BallMove(ball.get(), x, y);
        } else if (gizmo.isPresent()) {
            Gizmo g = gizmo.get();
            selected = g.name();
            gesture = new Gesture.GizmoMove(g, cell(x) - g.x(), cell(y) - g.y());
        } else {
            selected = isWall(x, y) ? Board.OUTER_WALLS : null;
        }
        stateChanged();
    }

    private void pressConnect(double x, double y) {
        Optional<String> end = gizmoAt(x, y).map(Gizmo::name)
                .or(() -> isWall(x, y) ? Optional.of(Board.OUTER_WALLS) : Optional.empty());
        if (end.isEmpty()) {
            say("Click a gizmo, or outside the board for the outer walls");
            return;
        }
        String name = end.get();
        if (connectSource == null) {
            connectSource = name;
            selected = name;
            say(tool.label() + ": source " + name + "; now click the gizmo it "
                    + (tool == Tool.CONNECT ? "should trigger" : "triggers"));
            stateChanged();
            return;
        }
        if (name.equals(Board.OUTER_WALLS)) {
            say("The outer walls can only be a trigger source: click a gizmo");
            return;
        }
        String source = connectSource;
        connectSource = null;
        if (tool == Tool.CONNECT) {
            edit("Connected " + source + " -> " + name, b -> b.connect(source, name));
        } else {
            disconnect(source, name);
        }
        stateChanged();
    }

    private void unbindKey(String gizmo, int keyCode) {
        List<KeyBinding> bindings = board.keyBindings().stream()
                .filter(k -> k.gizmo().equals(gizmo) && k.keyCode() == keyCode).toList();
        resetSteps();
        if (bindings.isEmpty()) {
            say(gizmo + " has no binding for key " + KeyEvent.getKeyText(keyCode));
        } else {
            edit("Unbound key " + KeyEvent.getKeyText(keyCode) + " from " + gizmo,
                    b -> bindings.forEach(k -> b.unbindKey(k.keyCode(), k.edge(), k.gizmo())));
        }
        stateChanged();
    }

    private boolean delete(String name) {
        if (name.equals(selected)) {
            selected = null;
        }
        return edit("Deleted " + name, b -> b.delete(name));
    }

    // ---- helpers ----

    private boolean edit(String success, Consumer<Board> operation) {
        try {
            history.perform(success, operation);
        } catch (BoardEditException refused) {
            say(refused.getMessage());
            stateChanged();
            return false;
        }
        say(success);
        edited();
        return true;
    }

    private Preview footprint(GizmoKind kind, int x, int y) {
        return new Preview.Footprint(x, y, kind.width(), kind.height(),
                board.placementProblem(kind, x, y, kind.width(), kind.height(), null));
    }

    private Preview absorberFootprint(int x0, int y0, int x1, int y1) {
        int x = Math.min(x0, x1);
        int y = Math.min(y0, y1);
        int w = Math.abs(x1 - x0) + 1;
        int h = Math.abs(y1 - y0) + 1;
        return new Preview.Footprint(x, y, w, h, board.placementProblem(GizmoKind.ABSORBER, x, y, w, h, null));
    }

    private Preview ballPlacement(double x, double y, double vx, double vy) {
        String name = names.nextBallName();
        return new Preview.BallPlacement(x, y, vx, vy, dryRun(b -> b.addBall(name, x, y, vx, vy)));
    }

    /** Asks the board itself (on a throw-away copy) whether an operation would be accepted. */
    private Optional<String> dryRun(Consumer<Board> operation) {
        try {
            operation.accept(board.copy());
            return Optional.empty();
        } catch (BoardEditException refused) {
            return Optional.of(refused.getMessage());
        }
    }

    private void setPreview(Preview next, boolean announce) {
        if (announce && next != null && next.problem().isPresent()
                && (preview == null || !next.problem().equals(preview.problem()))) {
            say(next.problem().get());
        }
        preview = next;
        stateChanged();
    }

    private Optional<Gizmo> gizmoAt(double x, double y) {
        return board.gizmoAt(cell(x), cell(y));
    }

    private Optional<Ball> ballNear(double x, double y) {
        return board.balls().stream()
                .filter(b -> Math.hypot(b.position().x() - x, b.position().y() - y) <= BALL_PICK_DISTANCE)
                .min(Comparator.comparingDouble(b -> Math.hypot(b.position().x() - x, b.position().y() - y)));
    }

    private boolean isWall(double x, double y) {
        boolean outside = x < 0 || y < 0 || x >= Board.SIZE || y >= Board.SIZE;
        boolean nearEdge = x < WALL_BAND || y < WALL_BAND || x > Board.SIZE - WALL_BAND || y > Board.SIZE - WALL_BAND;
        return outside || (nearEdge && gizmoAt(x, y).isEmpty());
    }

    private static boolean isDrag(Gesture.BallMove m, double x, double y) {
        return Math.hypot(x - m.pressX(), y - m.pressY()) >= DRAG_THRESHOLD;
    }

    private static double ballMoveTarget(double start, double press, double now) {
        return snap(start + now - press);
    }

    static int cell(double v) {
        return (int) Math.floor(v);
    }

    static double snap(double v) {
        return Math.round(v / BALL_SNAP) * BALL_SNAP;
    }

    private static double velocity(double drag) {
        // Whole L/s: typed-looking numbers in the properties panel and in saved files.
        return Math.round(drag * VELOCITY_PER_DRAG);
    }

    private OptionalDouble number(String label, String text) {
        try {
            return OptionalDouble.of(Double.parseDouble(text.trim()));
        } catch (NumberFormatException notANumber) {
            say(label + ": \"" + text.trim() + "\" is not a number");
            return OptionalDouble.empty();
        }
    }

    private void resetSteps() {
        gesture = null;
        preview = null;
        connectSource = null;
        keyGizmo = null;
        pendingKey = null;
    }

    private void say(String message) {
        messages.accept(message);
    }

    private void edited() {
        editListeners.forEach(Runnable::run);
        stateChanged();
    }

    private void stateChanged() {
        stateListeners.forEach(Runnable::run);
    }
}
