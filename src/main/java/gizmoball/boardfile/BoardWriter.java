package gizmoball.boardfile;

import gizmoball.model.Board;
import gizmoball.model.KeyBinding;
import gizmoball.model.game.GameRules;
import gizmoball.model.game.Tilt;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.PlayState;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.stream.Collectors;

/**
 * The canonical form of a board: one command per line, gizmos (in the board's order), then rotations, the
 * colours of gizmos that have their own, their own values (factors, plungers, spawn velocities, portals' pairs), the play state of flippers play has moved, balls, connections, key bindings,
 * gravity and friction, then the game: balls per game, the extra-ball score, the nudge, tilt and ball save, the drains and the gizmos' own points
 * (each only where the board has it, so a board without them is written as the standard format has it). Reading it
 * back gives an equal board.
 */
final class BoardWriter {

    private BoardWriter() {
    }

    static String toText(Board board) {
        return commands(board).stream().map(Command::toLine).collect(Collectors.joining("\n", "", "\n"));
    }

    /** The line of a gizmo's setting: the one place where each kind's setting meets its command word. */
    private static Command settingLine(String name, Setting setting) {
        if (setting instanceof Setting.Factor f) {
            return new Command.Factor(name, f.factor());
        }
        if (setting instanceof Setting.Pull p && p.plunger().isPresent()) {
            return new Command.MakePlunger(name, p.plunger().get());
        }
        if (setting instanceof Setting.Speed s) {
            return new Command.SpinnerSpeed(name, s.turnsPerSecond());
        }
        if (setting instanceof Setting.Launch l) {
            return new Command.SpawnVelocity(name, l.vx(), l.vy());
        }
        if (setting instanceof Setting.Pair p && p.portal().isPresent()) {
            return new Command.Pair(name, p.portal().get());
        }
        throw new IllegalArgumentException("no board-file line says " + setting);
    }

    /** The line that puts back what play changed of a gizmo: one per {@link PlayState} record but as built. */
    private static Command playStateLine(String name, PlayState state) {
        if (state instanceof PlayState.Swung s) {
            return new Command.FlipperState(name, s.degrees(), s.up());
        }
        if (state instanceof PlayState.Opened) {
            return new Command.CellOpen(name);
        }
        if (state instanceof PlayState.Turned t) {
            return new Command.SpinnerState(name, t.radians(), t.running());
        }
        throw new IllegalArgumentException("no board-file line says " + state);
    }

    static List<Command> commands(Board board) {
        List<Command> commands = new ArrayList<>();
        for (Gizmo gizmo : board.gizmos()) {
            commands.add(gizmo.kind().sizedByCorners()
                    ? new Command.AddAbsorber(gizmo.name(), gizmo.x(), gizmo.y(),
                            gizmo.x() + gizmo.width(), gizmo.y() + gizmo.height())
                    : new Command.AddGizmo(gizmo.kind(), gizmo.name(), gizmo.x(), gizmo.y()));
        }
        for (Gizmo gizmo : board.gizmos()) {
            commands.addAll(Collections.nCopies(gizmo.rotation(), new Command.Rotate(gizmo.name())));
        }
        for (Gizmo gizmo : board.gizmos()) {
            gizmo.colour().ifPresent(colour -> commands.add(new Command.Colour(gizmo.name(), colour)));
        }
        for (Gizmo gizmo : board.gizmos()) {
            Setting setting = gizmo.setting();
            if (!setting.isDefault() && setting.names().isEmpty()) {
                commands.add(settingLine(gizmo.name(), setting));
            }
        }
        // A setting that names other gizmos (a portal's pair) after every gizmo's own, once for the gizmos it joins.
        List<String> written = new ArrayList<>();
        for (Gizmo gizmo : board.gizmos()) {
            Setting setting = gizmo.setting();
            if (!setting.isDefault() && !setting.names().isEmpty() && !written.contains(gizmo.name())) {
                commands.add(settingLine(gizmo.name(), setting));
                written.addAll(setting.names());
            }
        }
        for (Gizmo gizmo : board.gizmos()) {
            // Only where play moved it: a board as built is written as before, and other implementations skip it.
            PlayState state = gizmo.playState();
            if (!(state instanceof PlayState.AsBuilt)) {
                commands.add(playStateLine(gizmo.name(), state));
            }
        }
        for (BallView ball : board.balls()) {
            // A captured ball sits at its absorber's corner with no velocity; written there, it is captured again.
            commands.add(new Command.AddBall(ball.name(), ball.position().x(), ball.position().y(),
                    ball.velocity().x(), ball.velocity().y()));
        }
        for (Connection connection : board.connections()) {
            commands.add(new Command.Connect(connection.source(), connection.target(), connection.order()));
        }
        for (KeyBinding binding : board.keyBindings()) {
            commands.add(new Command.KeyConnect(binding.keyCode(), binding.edge(), binding.gizmo(), binding.order()));
        }
        commands.add(new Command.Gravity(board.gravity()));
        commands.add(new Command.Friction(board.mu(), board.mu2()));
        commands.addAll(game(board));
        return commands.stream().map(c -> namesOurs(board, c) ? new Command.Marked(c) : c).toList();
    }

    /** Whether the command names a gizmo only this game has: a standard loader must skip it with the gizmo. */
    private static boolean namesOurs(Board board, Command command) {
        return command.references().stream()
                .anyMatch(name -> board.gizmo(name).filter(g -> CommandWord.of(g.kind()).ours()).isPresent());
    }

    private static List<Command> game(Board board) {
        GameRules rules = board.gameRules();
        List<Command> commands = new ArrayList<>();
        if (rules.isGame() || rules.ballsPerGame() != GameRules.DEFAULT_BALLS) {
            commands.add(new GameLine.BallsPerGame(rules.ballsPerGame()));
        }
        rules.extraBallAt().ifPresent(score -> commands.add(new GameLine.ExtraBall(score)));
        rules.nudge().ifPresent(nudge -> commands.add(new GameLine.NudgeLine(nudge)));
        if (!rules.tilt().equals(Tilt.DEFAULT)) {
            commands.add(new GameLine.TiltLine(rules.tilt()));
        }
        if (rules.ballSaveSeconds() > 0) {
            commands.add(new GameLine.BallSave(rules.ballSaveSeconds()));
        }
        board.gizmos().stream().filter(g -> rules.isDrain(g.name()))
                .forEach(g -> commands.add(new GameLine.Drain(g.name())));
        board.gizmos().stream().filter(g -> rules.ownPoints().containsKey(g.name()))
                .forEach(g -> commands.add(new GameLine.Points(g.name(), rules.ownPoints().get(g.name()))));
        return commands;
    }
}
