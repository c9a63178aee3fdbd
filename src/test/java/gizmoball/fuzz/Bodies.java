package gizmoball.fuzz;

import gizmoball.model.gizmo.Absorber;
import gizmoball.model.gizmo.Accelerator;
import gizmoball.model.gizmo.Bumper;
import gizmoball.model.gizmo.DropTargetView;
import gizmoball.model.gizmo.Flipper;
import gizmoball.model.gizmo.GateView;
import gizmoball.model.gizmo.PortalView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.Sink;
import gizmoball.model.gizmo.SpawnerView;
import gizmoball.model.gizmo.Spinner;

import java.util.List;

/**
 * The solid body of each gizmo, built from what a view may read (kind, footprint cell, size, rotation, a flipper's
 * angle, a spinner's) and the product description's shapes (docs/rules.md, "Gizmos"), never from the game's own
 * shapes or distances.
 */
final class Bodies {
    /** A flipper's bar: 2 L long with round ends of radius 0.25 L, so the ends' centres are 1.5 L apart. */
    static final double FLIPPER_RADIUS = 0.25;
    static final double FLIPPER_REACH = 1.5;
    static final double BUMPER_RADIUS = 0.5;

    private Bodies() {
    }

    static Solid of(Gizmo gizmo) {
        if (gizmo instanceof Bumper bumper) {
            return bumper(bumper);
        }
        if (gizmo instanceof Flipper flipper) {
            return flipper(flipper);
        }
        if (gizmo instanceof Spinner spinner) {
            return spinner(spinner);
        }
        if (gizmo instanceof Sink || gizmo instanceof PortalView || gizmo instanceof SpawnerView || switches(gizmo)) {
            return rectangle(gizmo.x(), gizmo.y(), 1, 1);   // a gate's or drop target's cell, when it is there
        }
        if (gizmo instanceof Accelerator accelerator) {
            return new Solid.Disc(new Point(accelerator.x() + 0.5, accelerator.y() + 0.5), BUMPER_RADIUS);
        }
        Absorber absorber = (Absorber) gizmo;
        return rectangle(absorber.x(), absorber.y(), absorber.width(), absorber.height());
    }

    /** Whether play makes its body come and go: a gate (open: no body) and a drop target (down: no body). */
    static boolean switches(Gizmo gizmo) {
        return gizmo instanceof GateView || gizmo instanceof DropTargetView;
    }

    /** Whether its body is there now: not for an open gate or a drop target that is down. */
    static boolean present(Gizmo gizmo) {
        return !(gizmo instanceof GateView gate && gate.isOpen() || gizmo instanceof DropTargetView target && target.isDown());
    }

    private static Solid bumper(Bumper bumper) {
        int x = bumper.x();
        int y = bumper.y();
        return switch (bumper.kind()) {
            case SQUARE -> rectangle(x, y, 1, 1);
            case CIRCLE -> new Solid.Disc(new Point(x + 0.5, y + 0.5), BUMPER_RADIUS);
            // Corners at top-left, top-right and bottom-left of the cell before it is turned.
            case TRIANGLE -> new Solid.Polygon(List.of(turned(bumper, x, y), turned(bumper, x + 1, y),
                    turned(bumper, x, y + 1)));
            default -> throw new IllegalArgumentException(bumper + " is no bumper kind the checker knows");
        };
    }

    private static Solid rectangle(int x, int y, int width, int height) {
        return new Solid.Polygon(List.of(new Point(x, y), new Point(x + width, y), new Point(x + width, y + height),
                new Point(x, y + height)));
    }

    /** The 2 x 2 box a flipper or a spinner turns in, whatever its angle and rotation. */
    static Solid box(Gizmo gizmo) {
        return rectangle(gizmo.x(), gizmo.y(), gizmo.width(), gizmo.height());
    }

    /**
     * A spinner's bar at its current angle (radians from +x toward +y): as a flipper's, 2 L long with round ends of
     * radius 0.25, centred on its box, so its ends' centres lie 0.75 L either side of the box's centre (issue 22).
     */
    static Solid.Capsule spinner(Spinner spinner) {
        double cx = spinner.x() + 1;
        double cy = spinner.y() + 1;
        double arm = FLIPPER_REACH / 2;
        double dx = arm * Math.cos(spinner.angle());
        double dy = arm * Math.sin(spinner.angle());
        return new Solid.Capsule(new Point(cx - dx, cy - dy), new Point(cx + dx, cy + dy), FLIPPER_RADIUS);
    }

    /**
     * The bar at its current angle. Before turning: a left flipper pivots at (x + 0.25, y + 0.25) and hangs down the
     * box's left edge, swinging toward the top edge (its tip from straight down toward +x); a right one mirrors it
     * about the box's vertical centre line.
     */
    static Solid.Capsule flipper(Flipper flipper) {
        boolean left = flipper.kind() == GizmoKind.LEFT_FLIPPER;
        double pivotX = flipper.x() + (left ? FLIPPER_RADIUS : 2 - FLIPPER_RADIUS);
        double pivotY = flipper.y() + FLIPPER_RADIUS;
        double angle = Math.toRadians(flipper.angleFromRest());
        double across = (left ? 1 : -1) * Math.sin(angle) * FLIPPER_REACH;
        double down = Math.cos(angle) * FLIPPER_REACH;
        return new Solid.Capsule(turned(flipper, pivotX, pivotY), turned(flipper, pivotX + across, pivotY + down),
                FLIPPER_RADIUS);
    }

    /** (px, py) turned clockwise on the screen (y down) by the gizmo's quarter turns about its footprint's centre. */
    static Point turned(Gizmo gizmo, double px, double py) {
        double cx = gizmo.x() + gizmo.width() / 2.0;
        double cy = gizmo.y() + gizmo.height() / 2.0;
        double dx = px - cx;
        double dy = py - cy;
        for (int i = 0; i < gizmo.rotation(); i++) {
            double next = -dy;
            dy = dx;
            dx = next;
        }
        return new Point(cx + dx, cy + dy);
    }
}
