package gizmoball.model;

/** The kinds of gizmo a board can hold, with the footprint each occupies (an absorber's size is per gizmo). */
public enum GizmoKind {
    SQUARE(1), CIRCLE(1), TRIANGLE(1), LEFT_FLIPPER(2), RIGHT_FLIPPER(2), ABSORBER(1);

    private final int side;

    GizmoKind(int side) {
        this.side = side;
    }

    public int width() {
        return side;
    }

    public int height() {
        return side;
    }
}
