package gizmoball.view.editor;

import gizmoball.boardfile.BoardContents;
import gizmoball.boardfile.BoardFiles;
import gizmoball.editor.Tool;
import gizmoball.model.Board;
import gizmoball.model.Invariants;
import gizmoball.model.KeyBinding;
import gizmoball.model.KeyEdge;
import gizmoball.model.game.GameRules;
import gizmoball.model.gizmo.AbsorberView;
import gizmoball.model.gizmo.FlipperView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.loop.BallView;
import gizmoball.model.loop.Connection;
import gizmoball.model.loop.TriggerSource;
import gizmoball.session.Mode;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.swing.JCheckBox;
import javax.swing.JMenuItem;
import javax.swing.JTextField;
import java.awt.event.KeyEvent;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.stream.Collectors;

import static gizmoball.view.Gui.onEdt;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

/**
 * The "done when": a board author makes the shipped default board from scratch in the editor (palette,
 * clicks, drags, Rotate, Connect, Key Connect with its popup, the properties panel), saves it, loads it back
 * unchanged, and plays it. The editor picks its own names, so the comparison with boards/default.txt maps them.
 */
class DefaultBoardFromScratchGuiTest {
    private BuildWindow w;

    @AfterEach
    void close() {
        if (w != null) {
            w.close();
        }
    }

    @Test
    void theDefaultBoardCanBeBuiltByHandSavedReloadedAndPlayed(@TempDir Path dir) throws Exception {
        Board target = BoardFiles.load(Path.of("boards", "default.txt"));
        w = BuildWindow.open();
        Map<String, String> editorName = new HashMap<>();

        // One event-thread task for the whole replay: the same events, without a thread hand-over per click.
        onEdt(() -> {
            for (Gizmo g : target.gizmos()) {
                place(g);
                editorName.put(g.name(), w.build.controller().selected().orElseThrow());
                // The game, in the placed gizmo's properties: its points where they are its own, a drain ticked.
                if (target.gameRules().ownPoints().containsKey(g.name())) {
                    JTextField points = EditorGui.find(w.build.properties(), JTextField.class, "gizmo.points");
                    points.setText(Integer.toString(target.gameRules().ownPoints().get(g.name())));
                    points.postActionEvent();
                }
                if (target.gameRules().isDrain(g.name())) {
                    EditorGui.find(w.build.properties(), JCheckBox.class, "gizmo.drain").doClick(0);
                }
                if (g.colour().isPresent()) {
                    JTextField colour = EditorGui.find(w.build.properties(), JTextField.class, "gizmo.colour");
                    colour.setText(String.format("#%02x%02x%02x", g.colour().get().red(), g.colour().get().green(),
                            g.colour().get().blue()));
                    colour.postActionEvent();
                }
                // A plunger: ticked, then its full-pull speed and pull time typed (Enter in the last applies both).
                if (g instanceof AbsorberView absorber && absorber.plunger().isPresent()) {
                    EditorGui.find(w.build.properties(), JCheckBox.class, "gizmo.plunger").doClick(0);
                    JTextField speed = EditorGui.find(w.build.properties(), JTextField.class, "gizmo.plunger.speed");
                    JTextField seconds = EditorGui.find(w.build.properties(), JTextField.class, "gizmo.plunger.seconds");
                    speed.setText(Double.toString(absorber.plunger().get().fullSpeed()));
                    seconds.setText(Double.toString(absorber.plunger().get().pullSeconds()));
                    seconds.postActionEvent();
                }
            }
            for (BallView b : target.balls()) {
                w.clickTool(Tool.BALL);
                w.drag(b.position().x(), b.position().y(), b.position().x() + b.velocity().x() / 10,
                        b.position().y() + b.velocity().y() / 10);
                editorName.put(b.name(), w.build.controller().selected().orElseThrow());
            }
            editorName.put(TriggerSource.OuterWalls.NAME, TriggerSource.OuterWalls.NAME);
            for (Connection c : target.connections()) {
                w.clickTool(Tool.CONNECT);
                clickOn(target, c.source().name());
                clickOn(target, c.target());
                w.build.controller().links().chooseConnection();   // the popup's Connect, its own action at once
            }
        });
        for (KeyBinding k : target.keyBindings()) {
            w.clickTool(Tool.KEY_CONNECT);
            clickOn(target, k.gizmo());
            w.key(k.keyCode());
            JMenuItem edge = onEdt(() -> EditorGui.showingMenuItem(k.edge() == KeyEdge.DOWN ? "edge.down" : "edge.up"));
            onEdt(() -> edge.doClick(0));
        }
        type("gravity", target.gravity());
        type("mu", target.mu());
        type("mu2", target.mu2());
        type("game.balls", target.gameRules().ballsPerGame());
        type("game.extra", target.gameRules().extraBallAt().orElseThrow());
        type("game.nudge", target.gameRules().nudge().orElseThrow().speed());   // on the default keys, the arrows

        Board built = w.board;
        assertThat(renamed(BoardContents.of(built), inverse(editorName))).isEqualTo(BoardContents.of(target));

        Path file = dir.resolve("by-hand.txt");
        onEdt(() -> {
            BoardFiles.save(built, file);
            return null;
        });
        Board reloaded = BoardFiles.load(file);
        assertThat(BoardContents.of(reloaded)).isEqualTo(onEdt(() -> BoardContents.of(built)));

        onEdt(() -> w.session.setMode(Mode.PLAY));
        String leftFlipper = editorName.get("LF");
        onEdt(() -> {
            built.keyDown(KeyEvent.VK_Z);
            for (int i = 0; i < 60; i++) {
                built.tick(Board.DEFAULT_TICK);
            }
        });
        assertThat(((FlipperView) built.gizmo(leftFlipper).orElseThrow()).angleFromRest()).isCloseTo(90, within(1e-9));
        assertThat(onEdt(() -> Invariants.violations(built))).isEmpty();
        // The ball waits in the absorber along the bottom, which is the game's drain, for Space.
        assertThat(onEdt(() -> built.balls().get(0).isCaptured())).isTrue();
        assertThat(onEdt(() -> built.game().ballsLeft())).isEqualTo(3);
    }

    private void place(Gizmo g) {
        Tool tool = switch (g.kind()) {
            case SQUARE -> Tool.SQUARE;
            case CIRCLE -> Tool.CIRCLE;
            case TRIANGLE -> Tool.TRIANGLE;
            case LEFT_FLIPPER -> Tool.LEFT_FLIPPER;
            case RIGHT_FLIPPER -> Tool.RIGHT_FLIPPER;
            case ABSORBER -> Tool.ABSORBER;
            case SINK -> Tool.SINK;
            case ACCELERATOR -> Tool.ACCELERATOR;
            case SPAWNER -> Tool.SPAWNER;
            case GATE -> Tool.GATE;
            case DROP_TARGET -> Tool.DROP_TARGET;
            case PORTAL -> Tool.PORTAL;
            case SPINNER -> Tool.SPINNER;
        };
        w.clickTool(tool);
        w.dragCells(g.x(), g.y(), g.x() + g.width() - 1, g.y() + g.height() - 1);
        if (g.rotation() > 0) {
            w.clickTool(Tool.ROTATE);
            for (int i = 0; i < g.rotation(); i++) {
                w.clickCell(g.x(), g.y());
            }
        }
    }

    /** Clicks a gizmo of the target board where it stands, or just left of the board for the outer walls. */
    private void clickOn(Board target, String name) {
        if (name.equals(TriggerSource.OuterWalls.NAME)) {
            w.click(-0.5, Board.SIZE / 2.0);
        } else {
            Gizmo g = target.gizmo(name).orElseThrow();
            w.clickCell(g.x(), g.y());
        }
    }

    private void type(String field, double value) {
        JTextField f = onEdt(() -> EditorGui.find(w.build.properties(), JTextField.class, field));
        onEdt(() -> {
            f.setText(Double.toString(value));
            f.postActionEvent();
        });
    }

    private static Map<String, String> inverse(Map<String, String> map) {
        Map<String, String> inverse = new HashMap<>();
        map.forEach((k, v) -> inverse.put(v, k));
        return inverse;
    }

    private static BoardContents renamed(BoardContents d, Map<String, String> name) {
        return new BoardContents(
                d.gizmos().stream().map(g -> new BoardContents.GizmoState(name.get(g.name()), g.kind(), g.x(), g.y(),
                        g.width(), g.height(), g.rotation(), g.colour(), g.setting().renamed(name::get))).toList(),
                d.balls().stream().map(b -> new BoardContents.BallState(name.get(b.name()), b.x(), b.y(), b.vx(),
                        b.vy(), b.captured())).toList(),
                d.connections().stream().map(c -> new Connection(TriggerSource.named(name.get(c.source().name())),
                        name.get(c.target()))).toList(),
                d.keyBindings().stream().map(k -> new KeyBinding(k.keyCode(), k.edge(), name.get(k.gizmo()))).toList(),
                d.gravity(), d.mu(), d.mu2(), new GameRules(d.game().ballsPerGame(),
                        d.game().drains().stream().map(name::get).collect(Collectors.toSet()),
                        d.game().ownPoints().entrySet().stream().collect(Collectors.toMap(e -> name.get(e.getKey()),
                                Map.Entry::getValue)), d.game().extraBallAt(), d.game().nudge(), d.game().tilt(),
                        d.game().ballSaveSeconds()));
    }
}
