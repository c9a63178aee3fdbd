package gizmoball.view.editor;

import gizmoball.editor.Editor;

import java.awt.Component;
import java.awt.Container;
import java.awt.GridBagConstraints;
import java.awt.Insets;
import java.awt.event.ActionEvent;
import java.awt.event.KeyEvent;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import javax.swing.AbstractAction;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.KeyStroke;

/**
 * What every section of the properties panel does with its fields alike: reads a group of numbers (reporting the
 * first bad one), keeps a refused value in its field with the reason, puts the board's values back on Esc, hands the
 * keyboard back to the board, and lays its rows out in the panel's grid.
 */
final class PanelFields {
    private final Editor controller;
    private final Runnable focusBoard;
    private final Runnable restore;

    /**
     * @param focusBoard gives the keyboard back to the board view (after Enter, Apply or Esc in a field)
     * @param restore    shows the board's values again in every field (Esc)
     */
    PanelFields(Editor controller, Runnable focusBoard, Runnable restore) {
        this.controller = controller;
        this.focusBoard = focusBoard;
        this.restore = restore;
    }

    /** After an apply: the keyboard back to the board if it was done, else what was typed kept and marked. */
    void applied(boolean done, Map<JTextField, String> typed) {
        if (done) {
            focusBoard.run();
        } else {
            keepRefused(typed);
        }
    }

    void focusBoard() {
        focusBoard.run();
    }

    /** The numbers of a group of fields; empty, with every bad field marked and the first reported, if any is bad. */
    Optional<double[]> values(NumberField... fields) {
        double[] values = new double[fields.length];
        NumberField firstBad = null;
        for (int i = 0; i < fields.length; i++) {
            OptionalDouble v = fields[i].value();
            if (v.isPresent()) {
                values[i] = v.getAsDouble();
            } else if (firstBad == null) {
                firstBad = fields[i];
            }
        }
        if (firstBad != null) {
            controller.tell(firstBad.getToolTipText());
            firstBad.requestFocusInWindow();
            return Optional.empty();
        }
        return Optional.of(values);
    }

    /**
     * A refused apply leaves what was typed in the fields that asked for the change, each marked with the reason
     * (a rolled-back edit has shown the board's values again meanwhile).
     */
    void keepRefused(Map<JTextField, String> typed) {
        String reason = controller.lastRefusal().orElse("refused");
        typed.forEach((field, text) -> {
            field.setText(text);
            RefusedValue.mark(field, reason);
        });
        typed.keySet().stream().findFirst().ifPresent(JTextField::requestFocusInWindow);
    }

    /** A value the panel itself refuses: said, kept in its field and marked, as every refused value is. */
    void refuse(JTextField field, String reason) {
        controller.tell(reason);
        RefusedValue.mark(field, reason);
        field.requestFocusInWindow();
    }

    /** Esc in a field puts the board's values back (dropping marks) and returns the keyboard to the board. */
    void restoreOnEscape(JTextField field) {
        field.getInputMap(JComponent.WHEN_FOCUSED).put(KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), "restore");
        field.getActionMap().put("restore", new AbstractAction() {
            @Override
            public void actionPerformed(ActionEvent e) {
                restore.run();
                focusBoard.run();
            }
        });
    }

    /** The typed texts of the fields whose numbers differ from the board's (the ones an apply changes). */
    static Map<JTextField, String> changed(NumberField[] fields, double[] now) {
        Map<JTextField, String> typed = new LinkedHashMap<>();
        for (int i = 0; i < fields.length; i++) {
            if (fields[i].differsFrom(now[i])) {
                typed.put(fields[i], fields[i].getText());
            }
        }
        return typed;
    }

    static void row(JPanel p, int y, String label, JComponent field) {
        p.add(new JLabel(label), constraints(0, y));
        p.add(field, constraints(1, y));
    }

    static GridBagConstraints constraints(int x, int y) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = x;
        c.gridy = y;
        c.anchor = GridBagConstraints.WEST;
        c.insets = new Insets(2, 2, 2, 2);
        c.fill = GridBagConstraints.HORIZONTAL;
        c.weightx = x;
        return c;
    }

    static GridBagConstraints wide(GridBagConstraints c) {
        c.gridwidth = 2;
        return c;
    }

    static void enableAll(Container rows, boolean enabled) {
        for (Component c : rows.getComponents()) {
            c.setEnabled(enabled);
            if (c instanceof Container inner) {
                enableAll(inner, enabled);
            }
        }
    }
}
