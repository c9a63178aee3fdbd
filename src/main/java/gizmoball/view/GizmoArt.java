package gizmoball.view;

import gizmoball.model.gizmo.AcceleratorView;
import gizmoball.model.gizmo.BarView;
import gizmoball.model.gizmo.BumperView;
import gizmoball.model.gizmo.DropTargetView;
import gizmoball.model.gizmo.Gizmo;
import gizmoball.model.gizmo.GateView;
import gizmoball.model.gizmo.GizmoKind;
import gizmoball.model.gizmo.PortalView;
import gizmoball.model.gizmo.SpawnerView;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import physics.Circle;
import physics.Vect;

/**
 * How each kind of gizmo is drawn, in board units: the one place of the board painter that knows the kinds
 * (docs/design.md, "Adding a gizmo kind"). {@link #of} is a switch over every kind without a default, so a new kind
 * does not compile until it says how it is drawn; each drawing says whether play changes it, its outline (where a
 * flash glows) and how it is painted.
 */
enum GizmoArt {
    /** A square or triangle bumper: its outline polygon. */
    POLYGON(gizmo -> polygon(((BumperView) gizmo).outline())),
    /** A circle bumper. */
    DISC(gizmo -> circle(((BumperView) gizmo).circle())),
    /** A flipper: its bar with round ends from the pivot, at the angle play has turned it to, and a hub at the pivot. */
    FLIPPER_BAR((gizmo, between) -> bar(gizmo, between, false)),
    /** A spinner: its bar with round ends across the pivot, at the angle play has turned it to, and a hub. */
    SPINNER_BAR((gizmo, between) -> bar(gizmo, between, true)),
    /** A sink: its cell, with the hole the balls go into. */
    SINK_HOLE(GizmoArt::cell) {
        @Override
        void paint(Graphics2D g, Gizmo gizmo, Interpolation between, Color fill, float pixel) {
            super.paint(g, gizmo, between, fill, pixel);
            g.setColor(BoardPainter.SINK_HOLE);
            g.fill(new Ellipse2D.Double(gizmo.x() + HOLE_MARGIN, gizmo.y() + HOLE_MARGIN, 1 - 2 * HOLE_MARGIN,
                    1 - 2 * HOLE_MARGIN));
        }
    },
    /** An accelerator: a disc with a ring, so that it is not taken for a circle bumper. */
    RINGED_DISC(gizmo -> circle(((AcceleratorView) gizmo).circle())) {
        @Override
        void paint(Graphics2D g, Gizmo gizmo, Interpolation between, Color fill, float pixel) {
            super.paint(g, gizmo, between, fill, pixel);
            Circle c = ((AcceleratorView) gizmo).circle();
            g.setColor(BoardPainter.ACCELERATOR_MARK);
            g.setStroke(new BasicStroke((float) RING_WIDTH));
            g.draw(circle(new Circle(c.getCenter(), c.getRadius() * RING_RADIUS)));
        }
    },
    /** A spawner: its cell, with an arrow to the mouth its balls come out of. */
    SPAWNER_MOUTH(GizmoArt::cell) {
        @Override
        void paint(Graphics2D g, Gizmo gizmo, Interpolation between, Color fill, float pixel) {
            super.paint(g, gizmo, between, fill, pixel);
            Vect centre = new Vect(gizmo.x() + 0.5, gizmo.y() + 0.5);
            Vect out = ((SpawnerView) gizmo).mouth(0).minus(centre);   // half a cell towards the mouth
            Vect across = new Vect(-out.y(), out.x());
            Path2D.Double arrow = new Path2D.Double();
            Vect tip = centre.plus(out.times(0.8));
            Vect left = centre.minus(out.times(0.3)).plus(across.times(0.6));
            Vect right = centre.minus(out.times(0.3)).minus(across.times(0.6));
            arrow.moveTo(tip.x(), tip.y());
            arrow.lineTo(left.x(), left.y());
            arrow.lineTo(right.x(), right.y());
            arrow.closePath();
            g.setColor(BoardPainter.SPAWNER_MARK);
            g.fill(arrow);
        }
    },
    /** A gate: its cell filled while closed, only a dashed outline of it while open. */
    GATE_CELL(GizmoArt::cell, true) {
        @Override
        void paint(Graphics2D g, Gizmo gizmo, Interpolation between, Color fill, float pixel) {
            if (!((GateView) gizmo).isOpen()) {
                super.paint(g, gizmo, between, fill, pixel);
                return;
            }
            g.setColor(fill);
            g.setStroke(new BasicStroke(2 * pixel, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10,
                    new float[] {0.15f, 0.1f}, 0));
            g.draw(new Rectangle2D.Double(gizmo.x() + pixel, gizmo.y() + pixel, 1 - 2 * pixel, 1 - 2 * pixel));
        }
    },
    /**
     * A drop target: up, its cell filled with a bull's-eye; down, only a flat strip along the bottom of the cell, the
     * target lying in its slot.
     */
    TARGET_CELL(GizmoArt::cell, true) {
        @Override
        void paint(Graphics2D g, Gizmo gizmo, Interpolation between, Color fill, float pixel) {
            if (((DropTargetView) gizmo).isDown()) {
                BoardPainter.paintShape(g, new Rectangle2D.Double(gizmo.x(), gizmo.y() + 1 - DOWN_STRIP, 1,
                        DOWN_STRIP), fill.darker(), pixel);
                return;
            }
            super.paint(g, gizmo, between, fill, pixel);
            g.setColor(BoardPainter.TARGET_MARK);
            g.setStroke(new BasicStroke((float) RING_WIDTH));
            g.draw(new Ellipse2D.Double(gizmo.x() + 0.2, gizmo.y() + 0.2, 0.6, 0.6));
            g.fill(new Ellipse2D.Double(gizmo.x() + 0.4, gizmo.y() + 0.4, 0.2, 0.2));
        }
    },
    /**
     * A portal: its cell, with a glowing band along the side its mouth faces while it has a pair (a portal without one
     * is a wall: its band is the cell's own colour, darker) and a dot toward the mouth.
     */
    PORTAL_CELL(GizmoArt::cell) {
        @Override
        void paint(Graphics2D g, Gizmo gizmo, Interpolation between, Color fill, float pixel) {
            super.paint(g, gizmo, between, fill, pixel);
            PortalView portal = (PortalView) gizmo;
            Vect out = portal.facing();
            Vect centre = new Vect(gizmo.x() + 0.5, gizmo.y() + 0.5);
            Vect bandCentre = centre.plus(out.times(0.5 - MOUTH_BAND / 2));
            double w = out.x() == 0 ? 1 - 2 * pixel : MOUTH_BAND;
            double h = out.x() == 0 ? MOUTH_BAND : 1 - 2 * pixel;
            g.setColor(portal.pair().isPresent() ? BoardPainter.PORTAL_MOUTH : fill.darker());
            g.fill(new Rectangle2D.Double(bandCentre.x() - w / 2, bandCentre.y() - h / 2, w, h));
            Vect dot = centre.minus(out.times(0.1));
            g.fill(new Ellipse2D.Double(dot.x() - 0.12, dot.y() - 0.12, 0.24, 0.24));
        }
    },
    /** An absorber: its whole footprint, whose size is the author's. */
    FOOTPRINT(gizmo -> new Rectangle2D.Double(gizmo.x(), gizmo.y(), gizmo.width(), gizmo.height()));

    /** The bar of a drawing that is one (then play changes it), null for every other. */
    private final BarOf barOf;
    /** The outline of a drawing that is no bar, null for a bar. */
    private final Outline outline;
    /** See {@link #changesInPlay()}. */
    private final boolean changesInPlay;

    /** A drawing with that outline, which play does not change. */
    GizmoArt(Outline outline) {
        this(outline, false);
    }

    /** A drawing with that outline, which play changes or not; not a bar. */
    GizmoArt(Outline outline, boolean changesInPlay) {
        this.barOf = null;
        this.outline = outline;
        this.changesInPlay = changesInPlay;
    }

    /** A bar: play turns it. */
    GizmoArt(BarOf barOf) {
        this.barOf = barOf;
        this.outline = null;
        this.changesInPlay = true;
    }

    /** How far (L) a sink's hole stays inside its cell. */
    private static final double HOLE_MARGIN = 0.15;
    /** L: how deep a portal's mouth band reaches into its cell. */
    private static final double MOUTH_BAND = 0.22;
    /** L: the height of a drop target that is down, lying at the bottom of its cell. */
    private static final double DOWN_STRIP = 0.15;
    /** An accelerator's ring: its radius as a part of the disc's, and its width in L. */
    private static final double RING_RADIUS = 0.5;
    private static final double RING_WIDTH = 0.07;

    /** How gizmos of that kind are drawn. */
    static GizmoArt of(GizmoKind kind) {
        return switch (kind) {
            case SQUARE, TRIANGLE -> POLYGON;
            case CIRCLE -> DISC;
            case LEFT_FLIPPER, RIGHT_FLIPPER -> FLIPPER_BAR;
            case ABSORBER -> FOOTPRINT;
            case SINK -> SINK_HOLE;
            case ACCELERATOR -> RINGED_DISC;
            case SPAWNER -> SPAWNER_MOUTH;
            case GATE -> GATE_CELL;
            case DROP_TARGET -> TARGET_CELL;
            case PORTAL -> PORTAL_CELL;
            case SPINNER -> SPINNER_BAR;
        };
    }

    /** The fill colour of a gizmo kind at rest. */
    static Color colourOf(GizmoKind kind) {
        return switch (kind) {
            case SQUARE -> new Color(0xe0483e);
            case CIRCLE -> new Color(0x3fbf5a);
            case TRIANGLE -> new Color(0x3d86f0);
            case LEFT_FLIPPER, RIGHT_FLIPPER -> new Color(0xf2b705);
            case ABSORBER -> new Color(0xb24fd6);
            case SINK -> new Color(0x5a6478);
            case ACCELERATOR -> new Color(0xff8a1f);
            case SPAWNER -> new Color(0x2bb3a6);
            case GATE -> new Color(0xc9a46b);
            case DROP_TARGET -> new Color(0xe8467c);
            case PORTAL -> new Color(0x6a5cff);
            case SPINNER -> new Color(0xb8d432);
        };
    }

    /**
     * Whether play changes how it looks: then it is painted with the moving part of the board, every frame; otherwise
     * with the fixed part, which only an edit changes (and again over it while it flashes).
     */
    boolean changesInPlay() {
        return changesInPlay;
    }

    /**
     * Its outline in board units as it is drawn now ({@code between} two ticks), where its flash glows: a bar's
     * stroked round-capped, else each drawing's own.
     */
    Shape outline(Gizmo gizmo, Interpolation between) {
        if (barOf == null) {
            return outline.of(gizmo);
        }
        Bar bar = barOf.at(gizmo, between);
        return roundCapped(2 * bar.radius()).createStrokedShape(bar.line());
    }

    /** Paints it in {@code fill}: a bar as a bar, by default its outline filled, with a one-pixel darker edge. */
    void paint(Graphics2D g, Gizmo gizmo, Interpolation between, Color fill, float pixel) {
        if (barOf != null) {
            barOf.at(gizmo, between).paint(g, fill, pixel);
        } else {
            BoardPainter.paintShape(g, outline(gizmo, between), fill, pixel);
        }
    }

    /** The outline of a drawing that play does not turn. */
    private interface Outline {
        Shape of(Gizmo gizmo);
    }

    /** A bar that turns (a flipper's, a spinner's) as drawn between two ticks. */
    private interface BarOf {
        Bar at(Gizmo gizmo, Interpolation between);
    }

    /** A bar from end centre to end centre, with round ends of {@code radius} and a hub at its pivot. */
    private record Bar(Line2D line, double radius, Vect pivot) {
        /** With a one-pixel darker edge and a darker hub. */
        void paint(Graphics2D g, Color fill, float pixel) {
            g.setColor(fill.darker());
            g.setStroke(roundCapped(2 * radius));
            g.draw(line);
            g.setColor(fill);
            g.setStroke(roundCapped(2 * radius - 2 * pixel));
            g.draw(line);
            double hub = radius / 3;
            g.setColor(fill.darker().darker());
            g.fill(new Ellipse2D.Double(pivot.x() - hub, pivot.y() - hub, 2 * hub, 2 * hub));
        }
    }

    /**
     * The turning bar at the angle drawn between two ticks: from its pivot to its tip, or {@code acrossPivot} from as
     * far the other side of the pivot.
     */
    private static Bar bar(Gizmo gizmo, Interpolation between, boolean acrossPivot) {
        BarView bar = (BarView) gizmo;
        Vect pivot = bar.pivot();
        Vect tip = between.tip(bar);
        Vect tail = acrossPivot ? pivot.minus(tip.minus(pivot)) : pivot;
        return new Bar(new Line2D.Double(tail.toPoint2D(), tip.toPoint2D()), bar.radius(), pivot);
    }

    private static BasicStroke roundCapped(double width) {
        return new BasicStroke((float) width, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND);
    }

    /** The gizmo's one cell. */
    private static Shape cell(Gizmo gizmo) {
        return new Rectangle2D.Double(gizmo.x(), gizmo.y(), 1, 1);
    }

    static Shape circle(Circle c) {
        Vect centre = c.getCenter();
        double r = c.getRadius();
        return new Ellipse2D.Double(centre.x() - r, centre.y() - r, 2 * r, 2 * r);
    }

    static Shape polygon(List<Vect> corners) {
        Path2D.Double path = new Path2D.Double();
        path.moveTo(corners.get(0).x(), corners.get(0).y());
        for (Vect corner : corners.subList(1, corners.size())) {
            path.lineTo(corner.x(), corner.y());
        }
        path.closePath();
        return path;
    }
}
