package gizmoball.view.editor;

import static gizmoball.view.editor.PanelFields.constraints;
import static gizmoball.view.editor.PanelFields.row;
import static gizmoball.view.editor.PanelFields.wide;

import gizmoball.editor.Editor;
import gizmoball.editor.PropertyEdits;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.Rgb;
import gizmoball.view.BoardPainter;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.GridBagLayout;
import java.awt.Window;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.Map;
import java.util.Optional;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JColorChooser;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;

/** The properties panel's colour rows: the selected gizmo's own colour as #rrggbb, a swatch, a chooser and a reset. */
final class ColourRows {
    private final Editor controller;
    private final PanelFields fields;
    private final JTextField colour = new JTextField(6);
    private final JLabel swatch = new JLabel();
    private final JPanel rows = new JPanel(new GridBagLayout());

    ColourRows(Editor controller, PanelFields fields) {
        this.controller = controller;
        this.fields = fields;
    }

    /** Shows the gizmo's colour (empty text: its kind's); with no gizmo the rows keep their room, disabled. */
    void show(Optional<Gizmo> gizmo) {
        PanelFields.enableAll(rows, gizmo.isPresent());
        colour.setText(gizmo.flatMap(Gizmo::colour).map(PropertyEdits::hex).orElse(""));
        RefusedValue.unmark(colour);
        swatch.setBackground(gizmo.map(BoardPainter::colourOf).orElse(rows.getBackground()));
    }

    JComponent component() {
        colour.setName("gizmo.colour");
        colour.setToolTipText("#rrggbb, or empty for the colour of the kind");
        colour.addActionListener(e -> apply(colour.getText()));
        swatch.setName("gizmo.colour.swatch");
        swatch.setOpaque(true);
        swatch.setPreferredSize(new Dimension(18, 18));
        swatch.setBorder(BorderFactory.createLineBorder(Color.DARK_GRAY));
        JPanel value = new JPanel(new BorderLayout(4, 0));
        value.add(swatch, BorderLayout.WEST);
        value.add(colour, BorderLayout.CENTER);
        row(rows, 0, "Colour", value);
        JButton choose = new JButton("Choose...");
        choose.setName("gizmo.colour.choose");
        choose.addActionListener(e -> {
            Color chosen = chooseColour(SwingUtilities.getWindowAncestor(rows),
                    "Colour of " + controller.selected().orElse(""), swatch.getBackground());
            if (chosen != null) {
                apply(PropertyEdits.hex(Rgb.of(chosen.getRGB())));
            }
        });
        JButton reset = new JButton("Kind's");
        reset.setName("gizmo.colour.reset");
        reset.setToolTipText("Back to the colour of the gizmo's kind");
        reset.addActionListener(e -> apply(""));
        // Under both columns: beside the label column they would not fit the panel's fixed width.
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT, 4, 0));
        buttons.add(choose);
        buttons.add(reset);
        rows.add(buttons, wide(constraints(0, 1)));
        return rows;
    }

    private void apply(String text) {
        controller.selectedGizmo().ifPresent(g -> fields.applied(controller.properties().setColour(g.name(), text),
                Map.of(colour, text)));
    }

    /**
     * The colour chosen in a modal chooser over the window, centred on it (over the panel it opened beside the window),
     * or null if cancelled: {@code JColorChooser.showDialog}, centred again once it is open, as an X server without a
     * window manager has been seen to leave it at the screen's corner (a CI run of WindowLayoutGuiTest).
     */
    private static Color chooseColour(Window window, String title, Color initial) {
        JColorChooser pane = new JColorChooser(initial);
        Color[] chosen = new Color[1];
        JDialog dialog = JColorChooser.createDialog(window, title, true, pane, ok -> chosen[0] = pane.getColor(), null);
        dialog.addWindowListener(new WindowAdapter() {
            @Override
            public void windowOpened(WindowEvent opened) {
                dialog.setLocationRelativeTo(window);
            }
        });
        dialog.setVisible(true);   // modal: returns once closed
        dialog.dispose();
        return chosen[0];
    }
}
