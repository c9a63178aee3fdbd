package gizmoball.view.editor;

import java.math.BigDecimal;
import java.math.RoundingMode;

/** Numbers as an author would type them: no trailing zeros ("25", "0.025", "-3.5"). */
final class Numbers {
    private Numbers() {
    }

    /** Exact (the shortest text that reads back as the same double), for fields whose text is applied back. */
    static String exact(double v) {
        return Double.isFinite(v) ? BigDecimal.valueOf(v).stripTrailingZeros().toPlainString() : Double.toString(v);
    }

    /** Rounded to two decimals, for labels on the board. */
    static String brief(double v) {
        return Double.isFinite(v)
                ? BigDecimal.valueOf(v).setScale(2, RoundingMode.HALF_EVEN).stripTrailingZeros().toPlainString()
                : Double.toString(v);
    }
}
