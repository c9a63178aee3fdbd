package gizmoball.model.gizmo;

import java.util.ArrayList;
import java.util.List;

import physics.Circle;
import physics.LineSegment;
import physics.Vect;

/**
 * The physical outline of a gizmo as the collision methods see it: line segments and circles. Polygons get a
 * zero-radius circle at every corner, so a ball hitting a corner reflects about the true contact normal. The
 * gizmos build their shapes; the board's loop reads them.
 */
public record Shape(List<LineSegment> segments, List<Circle> circles) {

    public Shape {
        segments = List.copyOf(segments);
        circles = List.copyOf(circles);
    }

    /** A closed polygon through the given corners (in order), with corner circles. */
    static Shape polygon(List<Vect> corners) {
        List<LineSegment> sides = new ArrayList<>();
        List<Circle> cornerCircles = new ArrayList<>();
        for (int i = 0; i < corners.size(); i++) {
            sides.add(new LineSegment(corners.get(i), corners.get((i + 1) % corners.size())));
            cornerCircles.add(new Circle(corners.get(i), 0));
        }
        return new Shape(sides, cornerCircles);
    }

    static Shape circle(Circle circle) {
        return new Shape(List.of(), List.of(circle));
    }
}
