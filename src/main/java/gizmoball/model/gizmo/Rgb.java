package gizmoball.model.gizmo;

/**
 * A gizmo's own colour, as plain red, green and blue channels 0..255 (the model draws nothing, so no AWT type).
 * A gizmo without one is drawn in its kind's colour, which the view chooses.
 */
public record Rgb(int red, int green, int blue) {
    public Rgb {
        if (!channel(red) || !channel(green) || !channel(blue)) {
            throw new IllegalArgumentException("colour channels must be 0..255, got " + red + " " + green + " " + blue);
        }
    }

    /** From 0xRRGGBB; any bits above the 24 of the colour (such as the alpha of a Java ARGB int) are ignored. */
    public static Rgb of(int packed) {
        return new Rgb((packed >> 16) & 0xff, (packed >> 8) & 0xff, packed & 0xff);
    }

    /** As 0xRRGGBB. */
    public int packed() {
        return red << 16 | green << 8 | blue;
    }

    private static boolean channel(int value) {
        return value >= 0 && value <= 255;
    }
}
