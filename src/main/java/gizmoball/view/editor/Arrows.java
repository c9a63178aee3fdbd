package gizmoball.view.editor;

import java.awt.geom.Path2D;

/** Arrow heads for connection arrows and velocity arrows. */
final class Arrows {
    private Arrows() {
    }

    /** A filled triangle with its tip at (x1, y1), pointing away from (x0, y0), {@code length} pixels long. */
    static Path2D head(double x0, double y0, double x1, double y1, double length) {
        double angle = Math.atan2(y1 - y0, x1 - x0);
        double spread = Math.toRadians(25);
        Path2D p = new Path2D.Double();
        p.moveTo(x1, y1);
        p.lineTo(x1 - length * Math.cos(angle - spread), y1 - length * Math.sin(angle - spread));
        p.lineTo(x1 - length * Math.cos(angle + spread), y1 - length * Math.sin(angle + spread));
        p.closePath();
        return p;
    }
}
