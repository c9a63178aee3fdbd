package gizmoball.view.editor;

import gizmoball.boardfile.Decimals;
import java.awt.Color;
import java.util.OptionalDouble;
import javax.swing.JTextField;

/**
 * A text field for one number of the board, read with the board file's own grammar ({@link Decimals}), so that
 * what the editor accepts is exactly what a saved file can hold. A field that does not read is marked as every
 * refused value is ({@link RefusedValue}) until it is fixed or its value is shown again.
 */
final class NumberField extends JTextField {
    static final Color MARK = RefusedValue.MARK;

    NumberField(String name) {
        super(7);
        setName(name);
    }

    /** The number typed, or empty (and the field marked) if the text is not a finite board-file decimal. */
    OptionalDouble value() {
        String text = getText().strip();
        OptionalDouble value = Decimals.parse(text);
        if (value.isEmpty()) {
            RefusedValue.mark(this, "\"" + text + "\" is not a number a board file can hold: write a finite decimal"
                    + " such as 25, -0.5 or 1e-3");
        } else {
            RefusedValue.unmark(this);
        }
        return value;
    }

    /** Shows {@code value} (as it would be typed), dropping any mark. */
    void show(double value) {
        setText(Numbers.exact(value));
        RefusedValue.unmark(this);
    }

    /** Whether the text shows another number than {@code value} (what an apply would change). */
    boolean differsFrom(double value) {
        OptionalDouble typed = Decimals.parse(getText().strip());
        return typed.isEmpty() || Double.compare(typed.getAsDouble(), value) != 0;
    }
}
