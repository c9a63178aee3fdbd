package gizmoball.lab;

/**
 * The mean, sample standard deviation, least and greatest of some numbers (all 0 for none; the deviation is 0 for
 * one). Summed in the order given, so the same numbers in the same order give the same figures to the last bit.
 */
public record Spread(double mean, double standardDeviation, double min, double max) {
    public static Spread of(double[] values) {
        if (values.length == 0) {
            return new Spread(0, 0, 0, 0);
        }
        double sum = 0;
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (double value : values) {
            sum += value;
            min = Math.min(min, value);
            max = Math.max(max, value);
        }
        double mean = sum / values.length;
        double squares = 0;
        for (double value : values) {
            squares += (value - mean) * (value - mean);
        }
        double deviation = values.length > 1 ? Math.sqrt(squares / (values.length - 1)) : 0;
        return new Spread(mean, deviation, min, max);
    }
}
