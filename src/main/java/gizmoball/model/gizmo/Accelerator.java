package gizmoball.model.gizmo;

import java.util.function.Function;

import physics.Circle;
import physics.Vect;

/**
 * A round 1x1 bumper that sends every ball that really hits it away faster: the bounce is elastic, then the speed is
 * multiplied by its factor, never beyond the board's speed limit (the loop applies both, {@link #boost}).
 */
public final class Accelerator extends GizmoBase implements AcceleratorView {
    static final double RADIUS = 0.5;
    private double factor = Setting.Factor.DEFAULT;

    Accelerator(String name, int x, int y) {
        super(name, GizmoKind.ACCELERATOR, x, y);
        rebuildShape();
    }

    private Accelerator(Accelerator other) {
        super(other);
        this.factor = other.factor;
    }

    @Override
    public double reflectionCoefficient() {
        return 1.0;
    }

    @Override
    public double factor() {
        return factor;
    }

    @Override
    public Setting setting() {
        return new Setting.Factor(factor);
    }

    @Override
    public void hold(Setting setting, Function<String, GizmoBase> gizmos) {
        factor = ((Setting.Factor) setting).factor();
    }

    /**
     * The velocity of a ball leaving it: {@code bounced} (the elastic bounce) times the factor, at most
     * {@code maxSpeed} fast. For the loop, not for views.
     */
    @Override
    public boolean boosts() {
        return true;
    }

    @Override
    public Vect boost(Vect bounced, double maxSpeed) {
        double speed = bounced.length();
        if (speed == 0) {
            return bounced;
        }
        return bounced.times(Math.min(factor, maxSpeed / speed));
    }

    @Override
    public Circle circle() {
        return new Circle(x() + 0.5, y() + 0.5, RADIUS);
    }

    @Override
    Shape buildShape() {
        return Shape.circle(circle());
    }

    @Override
    public double signedDistance(Vect p) {
        return Solids.toDisc(circle().getCenter(), RADIUS, p);
    }

    @Override
    public Accelerator copy() {
        return new Accelerator(this);
    }
}
