package gizmoball.boardfile;

import static gizmoball.boardfile.Decimals.format;

import gizmoball.model.Board;
import gizmoball.model.BoardEditException;
import gizmoball.model.KeyEdge;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Order;
import gizmoball.model.gizmo.Plunger;
import gizmoball.model.gizmo.Rgb;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.TriggerSource;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * One parsed board-file command: {@link #applyTo} performs it on a board through the board's own editing
 * operations (so every rule of the model applies), {@link #toLine()} writes it back in canonical form; each record
 * says only those two. What several commands share (what they need, define and state) is said once, by the kind of
 * command they are ({@link Adds}, {@link OfOne}, {@link AboutOne}, {@link OfTheBoard}); the lines of the board's game
 * are {@link GameLine}s. One sealed family, a record for each of the format's words, so that reading and writing have
 * one list of what a line can say.
 */
public sealed interface Command permits Command.Adds, Command.OfOne, Command.AboutOne, Command.OfTheBoard,
        Command.Marked, Command.Connect, Command.KeyConnect, Command.Pair, GameLine {

    /** Performs the command, or throws the board's refusal leaving the board as it was. */
    void applyTo(Board board);

    String toLine();

    /** The names of gizmos or balls that must exist for the command to apply (never OuterWalls). */
    default List<String> references() {
        return List.of();
    }

    /** The name of the gizmo or ball the command adds, if it adds one. */
    default Optional<String> defines() {
        return Optional.empty();
    }

    /**
     * The fact of the board that the line states, so that a save can tell the lines of what did not change from
     * the lines of what did (see {@link Subject}). A command that is one element of a set (a connection, a key
     * binding, and any command without a subject of its own) is its own subject.
     */
    default Subject subject() {
        return Subject.line(toLine());
    }

    /** A command that adds a gizmo or ball: it defines the name, and the thing is its subject. */
    sealed interface Adds extends Command {
        String name();

        @Override
        default Optional<String> defines() {
            return Optional.of(name());
        }

        @Override
        default Subject subject() {
            return Subject.thing(name());
        }
    }

    /** A command that acts on one named gizmo or ball, which must exist, and is its own subject. */
    sealed interface OfOne extends Command {
        String name();

        @Override
        default List<String> references() {
            return List.of(name());
        }
    }

    /**
     * A command that states one fact of one named gizmo (its colour, an accelerator's factor, where play left a
     * flipper): it needs that gizmo, and the fact is its subject, named by the command's record, one for each fact.
     */
    sealed interface AboutOne extends Command {
        String name();

        @Override
        default List<String> references() {
            return List.of(name());
        }

        @Override
        default Subject subject() {
            return new Subject(getClass().getSimpleName(), name());
        }
    }

    /**
     * A command that states one fact of the board itself (gravity, friction, a rule of its game): the fact is its
     * subject, named by the command's record, one for each fact.
     */
    sealed interface OfTheBoard extends Command permits Gravity, Friction, GameLine.BallsPerGame, GameLine.ExtraBall,
            GameLine.NudgeLine, GameLine.TiltLine, GameLine.BallSave {
        @Override
        default Subject subject() {
            return new Subject(getClass().getSimpleName(), "");
        }
    }

    /**
     * A standard command about something only this game has (an extension gizmo), written with {@code #@} before it
     * so that a loader of the standard format skips it with the gizmo's own line: {@code #@Connect SK LF}.
     */
    record Marked(Command command) implements Command {
        public void applyTo(Board board) {
            command.applyTo(board);
        }

        public String toLine() {
            String line = command.toLine();
            return line.startsWith(CommandWord.OURS) ? line : CommandWord.OURS + line;
        }

        public List<String> references() {
            return command.references();
        }

        public Optional<String> defines() {
            return command.defines();
        }

        public Subject subject() {
            return command.subject();
        }
    }

    /** Square, Circle, Triangle, LeftFlipper or RightFlipper with the top-left cell of its footprint. */
    record AddGizmo(GizmoKind kind, String name, int x, int y) implements Adds {
        public void applyTo(Board board) {
            board.addGizmo(kind, name, x, y);
        }

        public String toLine() {
            return CommandWord.of(kind).line(name, x, y);
        }
    }

    /** (x2, y2) is the exclusive bottom-right corner. */
    record AddAbsorber(String name, int x1, int y1, int x2, int y2) implements Adds {
        public void applyTo(Board board) {
            board.addAbsorber(name, x1, y1, x2, y2);
        }

        public String toLine() {
            return CommandWord.ABSORBER.line(name, x1, y1, x2, y2);
        }
    }

    record AddBall(String name, double x, double y, double vx, double vy) implements Adds {
        public void applyTo(Board board) {
            board.addBall(name, x, y, vx, vy);
        }

        public String toLine() {
            return CommandWord.BALL.line(name, format(x), format(y), format(vx), format(vy));
        }

        /** The same ball under another name (for a name another ball of the file already has). */
        AddBall named(String newName) {
            return new AddBall(newName, x, y, vx, vy);
        }
    }

    record Rotate(String name) implements AboutOne {
        public void applyTo(Board board) {
            board.rotate(name);
        }

        public String toLine() {
            return CommandWord.ROTATE.line(name);
        }
    }

    record Delete(String name) implements OfOne {
        public void applyTo(Board board) {
            board.delete(name);
        }

        public String toLine() {
            return CommandWord.DELETE.line(name);
        }
    }

    /** A gizmo to a whole cell or a ball centre anywhere: which one is known only once the name is resolved. */
    record Move(String name, double x, double y) implements OfOne {
        public void applyTo(Board board) {
            if (board.gizmo(name).isPresent()) {
                if (x != Math.rint(x) || y != Math.rint(y)) {
                    throw new BoardEditException("gizmo " + name + " can only move to a whole cell, not ("
                            + format(x) + ", " + format(y) + ")");
                }
                // A cast saturates, so a far-off cell stays far off and the board calls it outside.
                board.moveGizmo(name, (int) x, (int) y);
            } else if (board.ball(name).isPresent()) {
                board.moveBall(name, x, y);
            } else {
                throw new BoardEditException("cannot move " + name + ": no gizmo or ball named " + name);
            }
        }

        public String toLine() {
            return CommandWord.MOVE.line(name, format(x), format(y));
        }
    }

    /**
     * {@code source} as the file names it: the word {@code OuterWalls} is the outer walls. {@code order} is the
     * connection's action and delay: one of the standard format has neither; one with them is ours,
     * {@code #@Connect C1 LF raise after 0.25}.
     */
    record Connect(TriggerSource source, String target, Order order) implements Command {
        /** A connection of the standard format. */
        Connect(TriggerSource source, String target) {
            this(source, target, Order.DEFAULT);
        }

        public void applyTo(Board board) {
            board.connect(source, target, order);
        }

        public String toLine() {
            return (order.isDefault() ? "" : CommandWord.OURS) + CommandWord.CONNECT.spelling() + " " + source.name()
                    + " " + target + OrderWords.of(order);
        }

        public List<String> references() {
            return source instanceof TriggerSource.OfGizmo gizmo ? List.of(gizmo.gizmo(), target) : List.of(target);
        }
    }

    /**
     * {@code order} is the binding's action and delay: a binding of the standard format has neither and is written
     * as the standard format has it; one with them is ours, {@code #@KeyConnect key 32 down A fire after 0.5}.
     */
    record KeyConnect(int keyCode, KeyEdge edge, String gizmo, Order order) implements Command {
        /** A binding of the standard format. */
        KeyConnect(int keyCode, KeyEdge edge, String gizmo) {
            this(keyCode, edge, gizmo, Order.DEFAULT);
        }

        public void applyTo(Board board) {
            board.bindKey(keyCode, edge, gizmo, order);
        }

        public String toLine() {
            return (order.isDefault() ? "" : CommandWord.OURS) + CommandWord.KEY_CONNECT.spelling() + " key " + keyCode
                    + " " + edge.name().toLowerCase(Locale.ROOT) + " " + gizmo + OrderWords.of(order);
        }

        public List<String> references() {
            return List.of(gizmo);
        }
    }

    /** A gizmo's own colour, written {@code Colour <name> <red> <green> <blue>} (the spelling of two peers). */
    record Colour(String name, Rgb colour) implements AboutOne {
        public void applyTo(Board board) {
            board.setColour(name, Optional.of(colour));
        }

        public String toLine() {
            return CommandWord.COLOUR.line(name, colour.red(), colour.green(), colour.blue());
        }
    }

    /** {@code #@Factor <name> <factor>}: how many times faster the accelerator sends a ball away. */
    record Factor(String name, double factor) implements AboutOne {
        public void applyTo(Board board) {
            board.set(name, new Setting.Factor(factor));
        }

        public String toLine() {
            return CommandWord.FACTOR.line(name, format(factor));
        }
    }

    /** {@code #@Plunger <absorber> <full-speed> <pull-seconds>}: the absorber is a plunger. */
    record MakePlunger(String name, Plunger plunger) implements AboutOne {
        public void applyTo(Board board) {
            board.set(name, new Setting.Pull(Optional.of(plunger)));
        }

        public String toLine() {
            return CommandWord.PLUNGER.line(name, format(plunger.fullSpeed()), format(plunger.pullSeconds()));
        }
    }

    /** {@code #@Pair <portal> <portal>}: a ball entering either portal's mouth leaves by the other's. */
    record Pair(String first, String second) implements Command {
        public void applyTo(Board board) {
            board.set(first, new Setting.Pair(Optional.of(second)));
        }

        public String toLine() {
            return CommandWord.PAIR.line(first, second);
        }

        public List<String> references() {
            return List.of(first, second);
        }
    }

    /** {@code #@SpinnerSpeed <name> <turns>}: how many turns a second the spinner makes, negative anticlockwise. */
    record SpinnerSpeed(String name, double turnsPerSecond) implements AboutOne {
        public void applyTo(Board board) {
            board.set(name, new Setting.Speed(turnsPerSecond));
        }

        public String toLine() {
            return CommandWord.SPINNER_SPEED.line(name, format(turnsPerSecond));
        }
    }

    /** {@code #@SpinnerAngle <name> <radians> running|stopped}: where play left a spinner. */
    record SpinnerState(String name, double radians, boolean running) implements AboutOne {
        public void applyTo(Board board) {
            board.setSpinnerState(name, radians, running);
        }

        public String toLine() {
            return CommandWord.SPINNER_STATE.line(name, format(radians), running ? "running" : "stopped");
        }
    }

    /** {@code #@SpawnVelocity <name> <vx> <vy>}: the velocity of the balls the spawner adds. */
    record SpawnVelocity(String name, double vx, double vy) implements AboutOne {
        public void applyTo(Board board) {
            board.set(name, new Setting.Launch(vx, vy));
        }

        public String toLine() {
            return CommandWord.SPAWN_VELOCITY.line(name, format(vx), format(vy));
        }
    }

    /**
     * A flipper as play left it: {@code #@FlipperAngle <name> <degrees> up|down}, up when it swings (or stays) toward
     * its active stop. Written before the balls, which may lie where only the raised flipper leaves room.
     */
    record FlipperState(String name, double degrees, boolean active) implements AboutOne {
        public void applyTo(Board board) {
            board.setFlipperState(name, degrees, active);
        }

        public String toLine() {
            return CommandWord.FLIPPER_STATE.line(name, format(degrees), active ? "up" : "down");
        }
    }

    /**
     * {@code #@Open <name>}: a gate play has opened or a drop target it has knocked down: the cell is nothing (a board
     * saved during play).
     */
    record CellOpen(String name) implements AboutOne {
        public void applyTo(Board board) {
            board.setCellOpen(name);
        }

        public String toLine() {
            return CommandWord.CELL_OPEN.line(name);
        }
    }

    record Gravity(double g) implements OfTheBoard {
        public void applyTo(Board board) {
            board.setGravity(g);
        }

        public String toLine() {
            return CommandWord.GRAVITY.line(format(g));
        }
    }

    record Friction(double mu, double mu2) implements OfTheBoard {
        public void applyTo(Board board) {
            board.setFriction(mu, mu2);
        }

        public String toLine() {
            return CommandWord.FRICTION.line(format(mu), format(mu2));
        }
    }
}
