package gizmoball.view.editor;

import gizmoball.boardfile.Decimals;
import java.awt.Color;
import java.util.OptionalDouble;
import javax.swing.BorderFactory;
import javax.swing.JTextField;
import javax.swing.border.Border;

/**
 * A text field for one number of the board, read with the board file's own grammar ({@link Decimals}), so that
 * what the editor accepts is exactly what a saved file can hold. A field that does not read is marked (red
 * border, the reason as its tooltip) until it is fixed or its value is shown again.
 */
final class NumberField extends JTextField {
    static final Color MARK = new Color(0xD0, 0x20, 0x20);
    private final Border normal;

    NumberField(String name) {
        super(7);
        setName(name);
        normal = getBorder();
    }

    /** The number typed, or empty (and the field marked) if the text is not a finite board-file decimal. */
    OptionalDouble value() {
        String text = getText().strip();
        OptionalDouble value = Decimals.parse(text);
        if (value.isEmpty()) {
            setBorder(BorderFactory.createLineBorder(MARK, 2));
            setToolTipText("\"" + text + "\" is not a number a board file can hold: write a finite decimal such as "
                    + "25, -0.5 or 1e-3");
        } else {
            unmark();
        }
        return value;
    }

    /** Shows {@code value} (as it would be typed), dropping any mark. */
    void show(double value) {
        setText(Numbers.exact(value));
        unmark();
    }

    private void unmark() {
        setBorder(normal);
        setToolTipText(null);
    }
}
