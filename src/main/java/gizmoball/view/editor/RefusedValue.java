package gizmoball.view.editor;

import java.awt.Color;
import javax.swing.BorderFactory;
import javax.swing.JTextField;
import javax.swing.border.Border;

/**
 * The one way the properties panel shows a value it refused, whatever refused it (the number grammar, the model's
 * rules, the colour syntax): the value stays in its field as typed, the field is outlined in red, and the reason is
 * its tooltip, until the field is fixed or shows the board's value again.
 */
final class RefusedValue {
    static final Color MARK = new Color(0xD0, 0x20, 0x20);
    private static final String NORMAL_BORDER = "refusedValue.normalBorder";
    private static final String NORMAL_TOOLTIP = "refusedValue.normalTooltip";

    private RefusedValue() {
    }

    static void mark(JTextField field, String reason) {
        if (!isMarked(field)) {
            field.putClientProperty(NORMAL_BORDER, field.getBorder());
            field.putClientProperty(NORMAL_TOOLTIP, field.getToolTipText());
        }
        field.setBorder(BorderFactory.createLineBorder(MARK, 2));
        field.setToolTipText(reason);
    }

    static void unmark(JTextField field) {
        if (isMarked(field)) {
            field.setBorder((Border) field.getClientProperty(NORMAL_BORDER));
            field.setToolTipText((String) field.getClientProperty(NORMAL_TOOLTIP));
            field.putClientProperty(NORMAL_BORDER, null);
            field.putClientProperty(NORMAL_TOOLTIP, null);
        }
    }

    static boolean isMarked(JTextField field) {
        return field.getClientProperty(NORMAL_BORDER) != null;
    }
}
