package gizmoball.view.editor;

import gizmoball.boardfile.Decimals;
import gizmoball.editor.Editor;
import gizmoball.model.Board;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Plunger;
import gizmoball.model.gizmo.Setting;

import java.awt.FlowLayout;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;

/**
 * The properties panel's row for an absorber's {@link Setting.Pull}: whether it is a plunger, with its full-pull
 * speed and the seconds of holding a full pull takes.
 */
final class PlungerRow {
    private final Editor controller;
    private final PanelFields fields;
    private final JCheckBox plunger = new JCheckBox("Plunger");
    private final NumberField plungerSpeed = new NumberField("gizmo.plunger.speed");
    private final NumberField plungerSeconds = new NumberField("gizmo.plunger.seconds");

    PlungerRow(Editor controller, PanelFields fields) {
        this.controller = controller;
        this.fields = fields;
    }

    /** Shows the pull of the selected absorber; empty (nothing, or another kind selected) disables the row. */
    void show(Optional<Setting.Pull> absorber) {
        Optional<Plunger> pull = absorber.flatMap(Setting.Pull::plunger);
        plunger.setEnabled(absorber.isPresent());
        plunger.setSelected(pull.isPresent());
        for (NumberField f : new NumberField[] {plungerSpeed, plungerSeconds}) {
            f.setEnabled(pull.isPresent());
            f.setText("");
            RefusedValue.unmark(f);
        }
        pull.ifPresent(p -> {
            plungerSpeed.show(p.fullSpeed());
            plungerSeconds.show(p.pullSeconds());
        });
    }

    /** The check box and the full-pull speed and seconds, in one row. */
    JComponent component() {
        plunger.setName("gizmo.plunger");
        plunger.setToolTipText("Its key pulls it while held; the release launches faster the longer the hold");
        plunger.addActionListener(e -> apply());
        plungerSpeed.setToolTipText("A plunger: L/s of a full pull, above " + Decimals.format(Plunger.MIN_SPEED)
                + " and at most " + Decimals.format(Board.MAX_SPEED));
        plungerSeconds.setToolTipText("A plunger: seconds of holding for a full pull, "
                + Decimals.format(Plunger.MIN_PULL_SECONDS) + " to " + Decimals.format(Plunger.MAX_PULL_SECONDS));
        JPanel pull = new JPanel(new FlowLayout(FlowLayout.LEFT, 3, 0));
        pull.add(plunger);
        for (NumberField f : new NumberField[] {plungerSpeed, plungerSeconds}) {
            f.setColumns(3);
            f.addActionListener(e -> apply());
            fields.restoreOnEscape(f);
            pull.add(f);
            pull.add(new JLabel(f == plungerSpeed ? "L/s" : "s"));
        }
        return pull;
    }

    private void apply() {
        Optional<Gizmo> gizmo = controller.selectedGizmo();
        if (gizmo.isEmpty()) {
            return;
        }
        if (!plunger.isSelected()) {
            controller.properties().set(gizmo.get().name(), new Setting.Pull(Optional.empty()));
            fields.focusBoard();
            return;
        }
        NumberField[] numbers = {plungerSpeed, plungerSeconds};
        Optional<double[]> v = plungerSpeed.getText().isBlank() ? Optional.of(new double[] {
                Plunger.DEFAULT_FULL_SPEED, Plunger.DEFAULT_PULL_SECONDS}) : fields.values(numbers);
        if (v.isEmpty()) {
            return;
        }
        Map<JTextField, String> typed = new LinkedHashMap<>();
        for (NumberField f : numbers) {
            typed.put(f, f.getText());
        }
        fields.applied(controller.properties().set(gizmo.get().name(),
                new Setting.Pull(Optional.of(new Plunger(v.get()[0], v.get()[1])))), typed);
    }
}
