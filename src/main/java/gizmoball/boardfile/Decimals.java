package gizmoball.boardfile;

import java.math.BigDecimal;
import java.util.OptionalDouble;
import java.util.regex.Pattern;

/** Reads and writes the numbers of a board file. */
public final class Decimals {
    /*
     * Plain decimal notation with an optional exponent. Double.parseDouble alone would also take "NaN",
     * "Infinity", hexadecimal and a trailing 'd' or 'f', none of which another implementation could read back.
     */
    private static final Pattern DECIMAL = Pattern.compile("[+-]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][+-]?\\d+)?");
    private static final double LARGEST_EXACT_WHOLE = 1e15;

    private Decimals() {
    }

    /** The finite value of a decimal word, or empty if the word is not one. */
    public static OptionalDouble parse(String word) {
        if (!DECIMAL.matcher(word).matches()) {
            return OptionalDouble.empty();
        }
        double value = Double.parseDouble(word);
        return Double.isFinite(value) ? OptionalDouble.of(value) : OptionalDouble.empty();
    }

    /**
     * The shortest plain decimal that reads back to exactly {@code value}: whole numbers as {@code 7.0},
     * never an exponent (some readers split on letters), negative zero kept as {@code -0.0}.
     */
    public static String format(double value) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException("a board file holds only finite numbers, not " + value);
        }
        if (value == Math.rint(value) && Math.abs(value) < LARGEST_EXACT_WHOLE) {
            return (value == 0 && 1 / value < 0 ? "-" : "") + (long) value + ".0";
        }
        String shortest = Double.toString(value);
        if (shortest.indexOf('E') < 0) {
            return shortest;
        }
        String plain = new BigDecimal(shortest).stripTrailingZeros().toPlainString();
        return plain.contains(".") ? plain : plain + ".0";
    }
}
