package gizmoball.model.gizmo;

import java.util.List;
import java.util.Optional;
import java.util.function.Function;

import physics.Vect;

/**
 * A solid 1x1 cell with a mouth on the side it faces (up unturned, then right, down, left with each quarter turn),
 * paired with another portal. A ball that meets the mouth of a paired portal leaves by the mouth of its pair
 * ({@link #passage}), if the spot there is free; otherwise, and at the other three sides, the corners and every side
 * of a portal without a pair, it bounces as off a wall. The pair is the board's to keep (both portals name each
 * other); docs/design.md, "Portals", gives the geometry.
 */
public final class Portal extends PolygonGizmo implements PortalView {
    /** The index of the mouth among the segments of its shape: the side it faces. */
    public static final int MOUTH = 0;
    private String pair;

    Portal(String name, int x, int y) {
        super(name, GizmoKind.PORTAL, x, y);
        rebuildShape();
    }

    private Portal(Portal other) {
        super(other);
        this.pair = other.pair;
    }

    @Override
    public double reflectionCoefficient() {
        return 1.0;
    }

    @Override
    public Optional<String> pair() {
        return Optional.ofNullable(pair);
    }

    @Override
    public Setting setting() {
        return new Setting.Pair(pair());
    }

    /** Pairs both: each leaves the pair it had, whose other portal is left without one (a wall). */
    @Override
    public void hold(Setting setting, Function<String, GizmoBase> gizmos) {
        Optional<Portal> other = ((Setting.Pair) setting).portal().map(name -> (Portal) gizmos.apply(name));
        leavePair(gizmos);
        other.ifPresent(o -> {
            o.leavePair(gizmos);
            o.pair = name();
            pair = o.name();
        });
    }

    private void leavePair(Function<String, GizmoBase> gizmos) {
        pair().ifPresent(old -> ((Portal) gizmos.apply(old)).pair = null);
        pair = null;
    }

    /** Whether segment {@code index} of its shape is an open mouth: the mouth of a portal that has a pair. */
    public boolean opensAt(int index) {
        return pair != null && index == MOUTH;
    }

    @Override
    public Vect facing() {
        return turn(new Vect(0, -1), rotation());
    }

    /** The middle of its mouth, on the edge of its cell. */
    public Vect mouthCentre() {
        return new Vect(x() + 0.5, y() + 0.5).plus(facing().times(0.5));
    }

    /**
     * Where and how fast a ball of radius {@code radius} centred at {@code centre}, touching this portal's mouth, leaves
     * by the mouth of {@code exit}: its offset from this mouth and its velocity turned by the quarter turns q that take
     * this portal's facing to the opposite of the exit's (q = exit rotation + 2 - this rotation, mod 4: a ball going in
     * comes out), then pushed out by its diameter, so that it touches the exit's mouth from outside as it touched this
     * one. Exact: a quarter turn only swaps and negates components.
     */
    public Passage passage(Vect centre, Vect velocity, Portal exit, double radius) {
        int quarterTurns = Math.floorMod(exit.rotation() + 2 - rotation(), 4);
        Vect offset = turn(centre.minus(mouthCentre()), quarterTurns);
        return new Passage(name(), exit.name(), exit.mouthCentre().plus(offset).plus(exit.facing().times(2 * radius)),
                turn(velocity, quarterTurns));
    }

    /** The vector turned clockwise on the screen (y down) by {@code quarterTurns}: (x, y) to (-y, x) each. */
    static Vect turn(Vect v, int quarterTurns) {
        return switch (Math.floorMod(quarterTurns, 4)) {
            case 0 -> v;
            case 1 -> new Vect(-v.y(), v.x());
            case 2 -> new Vect(-v.x(), -v.y());
            default -> new Vect(v.y(), -v.x());
        };
    }

    /** Its cell's corners from the first corner of its mouth, clockwise, so that side 0 is the mouth. */
    @Override
    List<Vect> outline() {
        return List.of(rotated(x(), y()), rotated(x() + 1, y()), rotated(x() + 1, y() + 1), rotated(x(), y() + 1));
    }

    @Override
    public Portal copy() {
        return new Portal(this);
    }
}
