package gizmoball.view.editor;

import gizmoball.boardfile.Decimals;
import gizmoball.editor.Editor;
import gizmoball.model.Board;
import gizmoball.model.game.GameRules;

import java.awt.BorderLayout;
import java.awt.GridBagLayout;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalLong;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;

/**
 * The properties panel's Board section: gravity, friction, the balls of a game, the extra-ball score, and the table's
 * nudge, tilt and ball save.
 */
final class BoardSection {
    private final Editor controller;
    private final PanelFields fields;
    private final NumberField gravity = new NumberField("gravity");
    private final NumberField mu = new NumberField("mu");
    private final NumberField mu2 = new NumberField("mu2");
    private final NumberField balls = new NumberField("game.balls");
    private final JTextField extraBall = new JTextField(7);
    private final JTextField nudgeSpeed = new JTextField(7);
    private final NumberField tiltNudges = new NumberField("game.tilt.nudges");
    private final NumberField tiltSeconds = new NumberField("game.tilt.seconds");
    private final NumberField ballSave = new NumberField("game.ballsave");

    BoardSection(Editor controller, PanelFields fields) {
        this.controller = controller;
        this.fields = fields;
    }

    /** Shows the board's values. */
    void show(Board board) {
        gravity.show(board.gravity());
        mu.show(board.mu());
        mu2.show(board.mu2());
        balls.setText(Integer.toString(board.gameRules().ballsPerGame()));
        extraBall.setText(board.gameRules().extraBallAt().isPresent()
                ? Long.toString(board.gameRules().extraBallAt().getAsLong()) : "");
        RefusedValue.unmark(extraBall);
        GameRules rules = board.gameRules();
        nudgeSpeed.setText(rules.nudge().map(n -> Decimals.format(n.speed())).orElse(""));
        tiltNudges.show(rules.tilt().nudges());
        tiltSeconds.show(rules.tilt().seconds());
        ballSave.show(rules.ballSaveSeconds());
        for (JTextField f : new JTextField[] {nudgeSpeed, tiltNudges, tiltSeconds, ballSave}) {
            RefusedValue.unmark(f);
        }
    }

    JComponent component() {
        JPanel p = new JPanel(new GridBagLayout());
        PanelFields.row(p, 0, "Gravity (L/s\u00b2)", gravity);
        PanelFields.row(p, 1, "mu (per s)", mu);
        PanelFields.row(p, 2, "mu2 (per L)", mu2);
        PanelFields.row(p, 3, "Balls a game", balls);
        extraBall.setName("game.extra");
        extraBall.setToolTipText("The score that gives one extra ball; empty for none");
        PanelFields.row(p, 4, "Extra ball at", extraBall);
        nudgeSpeed.setName("game.nudge");
        nudgeSpeed.setToolTipText("L/s a nudge (arrow keys unless the file says) adds to every free ball; empty: none");
        PanelFields.row(p, 5, "Nudge (L/s)", nudgeSpeed);
        tiltNudges.setToolTipText("The nudge that tilts: that many within the seconds beside it");
        tiltSeconds.setToolTipText("The seconds within which that many nudges tilt");
        JPanel tilt = new JPanel(new BorderLayout(4, 0));
        tiltNudges.setColumns(2);
        tilt.add(tiltNudges, BorderLayout.WEST);
        tilt.add(new JLabel("in"), BorderLayout.CENTER);
        tiltSeconds.setColumns(3);
        JPanel seconds = new JPanel(new BorderLayout(4, 0));
        seconds.add(tiltSeconds, BorderLayout.CENTER);
        seconds.add(new JLabel("s"), BorderLayout.EAST);
        tilt.add(seconds, BorderLayout.EAST);
        PanelFields.row(p, 6, "Tilt: nudges", tilt);
        ballSave.setToolTipText("Seconds after a launch in which a drained ball is given back, once; 0: none");
        PanelFields.row(p, 7, "Ball save (s)", ballSave);
        JButton apply = new JButton("Apply");
        apply.setName("board.apply");
        apply.addActionListener(e -> apply());
        for (JTextField f : new JTextField[]{gravity, mu, mu2, balls, extraBall, nudgeSpeed, tiltNudges, tiltSeconds,
                ballSave}) {
            f.addActionListener(e -> apply());
            fields.restoreOnEscape(f);
        }
        p.add(apply, PanelFields.constraints(1, 8));
        return p;
    }

    private void apply() {
        NumberField[] constants = {gravity, mu, mu2};
        Optional<double[]> v = fields.values(gravity, mu, mu2, balls);
        if (v.isEmpty()) {
            return;
        }
        OptionalLong extra = OptionalLong.empty();
        String extraText = extraBall.getText().strip();
        if (!extraText.isEmpty()) {
            OptionalDouble score = Decimals.parse(extraText);
            if (score.isEmpty() || score.getAsDouble() != Math.rint(score.getAsDouble())) {
                fields.refuse(extraBall, "Extra ball at '" + extraText
                        + "': write a whole score, or nothing for no extra ball");
                return;
            }
            extra = OptionalLong.of((long) score.getAsDouble());
        }
        if (v.get()[3] != Math.rint(v.get()[3]) || Math.abs(v.get()[3]) > Integer.MAX_VALUE) {
            fields.refuse(balls, "Balls a game: a whole number, 1 to " + GameRules.MAX_BALLS);
            return;
        }
        Board board = controller.board();
        Map<JTextField, String> typed = PanelFields.changed(constants,
                new double[] {board.gravity(), board.mu(), board.mu2()});
        if (!controller.properties().setConstants(v.get()[0], v.get()[1], v.get()[2])) {
            fields.keepRefused(typed);
            return;
        }
        Map<JTextField, String> game = new LinkedHashMap<>();
        game.put(balls, balls.getText());
        game.put(extraBall, extraBall.getText());
        if (!controller.properties().setGame((int) v.get()[3], extra)) {
            fields.keepRefused(game);
            return;
        }
        applyTable();
    }

    /** The table's nudge, tilt and ball save, applied with the rest of the section. */
    private void applyTable() {
        Optional<double[]> v = fields.values(tiltNudges, tiltSeconds, ballSave);
        String speedText = nudgeSpeed.getText().strip();
        OptionalDouble speed = speedText.isEmpty() ? OptionalDouble.empty() : Decimals.parse(speedText);
        if (v.isEmpty() || !speedText.isEmpty() && speed.isEmpty()) {
            if (v.isPresent()) {
                fields.refuse(nudgeSpeed, "Nudge '" + speedText + "' is not a number of L/s");
            }
            return;
        }
        Map<JTextField, String> typed = new LinkedHashMap<>();
        for (JTextField f : new JTextField[] {nudgeSpeed, tiltNudges, tiltSeconds, ballSave}) {
            typed.put(f, f.getText());
        }
        fields.applied(controller.properties().setTable(speed, v.get()[0], v.get()[1], v.get()[2]), typed);
    }
}
