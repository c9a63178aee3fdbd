package gizmoball.view.editor;

import static gizmoball.view.editor.PanelFields.changed;
import static gizmoball.view.editor.PanelFields.constraints;
import static gizmoball.view.editor.PanelFields.row;

import gizmoball.editor.Editor;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Setting;
import gizmoball.model.loop.BallView;

import java.awt.GridBagLayout;
import java.util.Map;
import java.util.Optional;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.JTextField;

/**
 * The properties panel's ball rows: a ball's centre and velocity, or a spawner's {@link Setting.Launch} in the vx and
 * vy fields (its balls are what they describe). With neither selected they keep their room, empty and disabled.
 */
final class BallRows {
    private final Editor controller;
    private final PanelFields fields;
    private final NumberField ballX = new NumberField("ball.x");
    private final NumberField ballY = new NumberField("ball.y");
    private final NumberField ballVx = new NumberField("ball.vx");
    private final NumberField ballVy = new NumberField("ball.vy");
    private final JButton applyBall = new JButton("Apply");
    private final JPanel rows = new JPanel(new GridBagLayout());

    BallRows(Editor controller, PanelFields fields) {
        this.controller = controller;
        this.fields = fields;
    }

    void show(Optional<BallView> ball, Optional<Setting.Launch> launch) {
        for (NumberField f : new NumberField[]{ballX, ballY, ballVx, ballVy}) {
            f.setEnabled(ball.isPresent());
            if (ball.isEmpty()) {
                f.setText("");
            }
        }
        applyBall.setEnabled(ball.isPresent() || launch.isPresent());
        launch.ifPresent(l -> {
            ballVx.setEnabled(true);
            ballVy.setEnabled(true);
            ballVx.show(l.vx());
            ballVy.show(l.vy());
        });
        ball.ifPresent(b -> {
            ballX.show(b.position().x());
            ballY.show(b.position().y());
            ballVx.show(b.velocity().x());
            ballVy.show(b.velocity().y());
        });
    }

    JComponent component() {
        row(rows, 0, "Ball x", ballX);
        row(rows, 1, "Ball y", ballY);
        row(rows, 2, "vx (L/s)", ballVx);
        row(rows, 3, "vy (L/s)", ballVy);
        applyBall.setName("ball.apply");
        applyBall.addActionListener(e -> apply());
        for (NumberField f : new NumberField[]{ballX, ballY, ballVx, ballVy}) {
            f.addActionListener(e -> apply());
            fields.restoreOnEscape(f);
        }
        rows.add(applyBall, constraints(1, 4));
        return rows;
    }

    private void apply() {
        Optional<Gizmo> spawner = controller.selectedGizmo().filter(g -> g.setting() instanceof Setting.Launch);
        if (spawner.isPresent()) {
            applySpawnVelocity(spawner.get().name(), (Setting.Launch) spawner.get().setting());
            return;
        }
        Optional<BallView> ball = controller.selectedBall();
        NumberField[] numbers = {ballX, ballY, ballVx, ballVy};
        Optional<double[]> v = fields.values(numbers);
        if (ball.isEmpty() || v.isEmpty()) {
            return;
        }
        BallView b = ball.get();
        Map<JTextField, String> typed = changed(numbers,
                new double[] {b.position().x(), b.position().y(), b.velocity().x(), b.velocity().y()});
        fields.applied(controller.properties().setBall(b.name(), v.get()[0], v.get()[1], v.get()[2], v.get()[3]),
                typed);
    }

    private void applySpawnVelocity(String spawner, Setting.Launch now) {
        NumberField[] numbers = {ballVx, ballVy};
        Optional<double[]> v = fields.values(numbers);
        if (v.isEmpty()) {
            return;
        }
        Map<JTextField, String> typed = changed(numbers, new double[] {now.vx(), now.vy()});
        fields.applied(controller.properties().set(spawner, new Setting.Launch(v.get()[0], v.get()[1])), typed);
    }
}
